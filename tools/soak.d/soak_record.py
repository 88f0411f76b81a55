"""What the soak counts and what it knows about the faults it injected.

Stats: calls and their latencies per client, failures by cause (inside or
outside a fault window), events, defects (a wrong value, a double motion, a
lost NVM, a crash or a leak: each makes the run fail), RSS and fd samples.
FaultLog: the bus-fault windows, so that a client can tell an answer lost
to a fault it was meant to lose from one lost outside any fault."""
import collections
import threading
import time

# a fault's effect can show a little before its directive is sent (the
# client's request already on its way) and a little after it ends
FAULT_MARGIN = 0.1


class Stats:
    def __init__(self):
        self.lock = threading.Lock()
        self.calls = collections.Counter()
        self.latencies = collections.defaultdict(list)
        self.failures = collections.Counter()     # (client, cause, in a fault window)
        self.events = collections.Counter()
        self.defects = []
        self.samples = []                         # (seconds, pid, rss kB, fds)
        self.landing_errors = []
        self.started = time.monotonic()
        self.trace_file = None

    def trace(self, text):
        """A line in the --trace file (what each client did, each fault)."""
        if self.trace_file is not None:
            with self.lock:
                self.trace_file.write("%9.3f %s\n" % (time.monotonic() - self.started, text))

    def call(self, client, seconds):
        with self.lock:
            self.calls[client] += 1
            self.latencies[client].append(seconds)

    def total_calls(self):
        with self.lock:
            return sum(self.calls.values())

    def failure(self, client, cause, in_fault):
        self.trace("%s: failed: %s%s" % (client, cause, "" if in_fault else " OUTSIDE any fault"))
        with self.lock:
            self.failures[(client, cause, in_fault)] += 1

    def event(self, name, count=1):
        with self.lock:
            self.events[name] += count

    def defect(self, text):
        self.trace("DEFECT " + text)
        with self.lock:
            self.defects.append("%7.1f s  %s" % (time.monotonic() - self.started, text))
        print("soak: DEFECT: %s" % text, flush=True)

    def landed(self, error):
        with self.lock:
            self.landing_errors.append(abs(error))

    def sample(self, pid, rss, fds):
        with self.lock:
            self.samples.append((time.monotonic() - self.started, pid, rss, fds))


def percentile(values, fraction):
    if not values:
        return float("nan")
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


class FaultLog:
    """Bus-fault windows: [start, end (None while active), kind, drives hit]."""

    def __init__(self):
        self.lock = threading.Condition()
        self.windows = []
        self.open_windows = set()

    def begin(self, kind, drives):
        with self.lock:
            self.windows.append([time.monotonic(), None, kind, frozenset(drives)])
            self.open_windows.add(len(self.windows) - 1)
            return len(self.windows) - 1

    def end(self, index):
        with self.lock:
            self.windows[index][1] = time.monotonic()
            self.open_windows.discard(index)
            self.lock.notify_all()

    def overlapped(self, start, end, drive):
        """Whether a fault hitting @drive was active at any time in
        [@start, @end] (with FAULT_MARGIN on both sides)."""
        with self.lock:
            for began, ended, _, drives in reversed(self.windows):
                if ended is not None and ended + 60 < start:
                    break   # one after the other: the older ones ended even earlier
                if drive in drives and began - FAULT_MARGIN <= end and (
                        ended is None or ended + FAULT_MARGIN >= start):
                    return True
            return False

    def active(self, drive):
        with self.lock:
            return any(self.windows[i][1] is None and drive in self.windows[i][3]
                       for i in self.open_windows)

    def wait_quiet(self, drive, timeout):
        """Until no fault hits @drive (at most @timeout), then FAULT_MARGIN
        more so that frames held back by it have come out."""
        end = time.monotonic() + timeout
        with self.lock:
            while self.active(drive) and time.monotonic() < end:
                self.lock.wait(min(0.05, max(0.0, end - time.monotonic())))
        time.sleep(FAULT_MARGIN)


class Gate:
    """Clients pass it shared, one operation at a time; a restart of
    daran-sim takes it alone (every client between two operations)."""

    def __init__(self):
        self.cond = threading.Condition()
        self.sharers = 0
        self.exclusive = False

    def enter(self):
        with self.cond:
            while self.exclusive:
                self.cond.wait()
            self.sharers += 1

    def leave(self):
        with self.cond:
            self.sharers -= 1
            self.cond.notify_all()

    def take(self):
        with self.cond:
            while self.exclusive:
                self.cond.wait()
            self.exclusive = True
            while self.sharers:
                self.cond.wait()

    def give(self):
        with self.cond:
            self.exclusive = False
            self.cond.notify_all()
