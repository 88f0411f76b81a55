"""A client's operations on its drives and the checks on their outcome.

Each client (the vendor-like ASCII client on drive 1, the bridge client on
drives 2 and 3, the CAN client on drive 4) runs one operation at a time,
holding its drive's lock (so a power cycle falls between operations), and
ends every operation knowing the truth: what the drive holds now (read
back, retried after the fault window when a fault took the answer), and
which values its NVM may hold (one when the save surely happened, the old
ones too when a fault may have taken it). A value outside what is possible
is a defect; so is a move that lands elsewhere than its target, or at
start + 2 x distance (run twice), or a shaft that moved between moves."""
import math
import time

from soak_links import PROPERTIES, LinkDown, NoAnswer, f32, same_value, shown

LANDING_TOLERANCE = 0.5      # deg: the controller's tracking after trajectory_done
SETTLE = 0.1                 # s after trajectory_done before the landing is read
# what a fault may take: the gateway's and the CAN client's "no answer"
FAULT_CAUSES = ("error: no reply", "error: bus error", "CAN: no reply")
RETRY_FOR = 20.0             # s: a drive that answers nothing this long outside faults is a defect
MOVE_VEL = 300               # r/min (within the CAN frames' s16 x 100)
MOVE_ACC = 300               # (r/min)/s


class Unrecovered(Exception):
    """A drive that kept silent past RETRY_FOR: reported as a defect."""


class DriveModel:
    def __init__(self):
        self.live = {}            # path -> value it holds (None: not established)
        self.saved = {}           # path -> values its NVM may hold
        self.verify_pending = True
        self.landing = None       # where its last move ended (None: unknown)

    def power_lost(self):
        """A power cycle or restart: config comes back from NVM."""
        self.verify_pending = True


def trapezoid_time(distance, vel, acc):
    v = vel * 6.0
    a = acc * 6.0
    d = abs(distance)
    if d <= v * v / a:
        return 2.0 * math.sqrt(d / a)
    return d / v + v / a


def random_value(rng, kind):
    if kind == "f32":
        return f32(round(rng.uniform(1.0, 500.0), rng.choice((0, 1, 2, 3))))
    if kind == "s32":
        return rng.randint(-2 ** 31, 2 ** 31 - 1)
    return rng.randint(0, 1)


class Client:
    OPERATIONS = (("write_read", 50), ("move_to", 17), ("move_by", 17), ("save", 10), ("peek", 6))

    def __init__(self, name, paths, stats, faults, gate, drive_locks, rng, stop, peek=None):
        self.name = name
        self.paths = paths                  # drive -> AsciiPath / CanPath
        self.models = {drive: DriveModel() for drive in paths}
        self.stats = stats
        self.faults = faults
        self.gate = gate
        self.drive_locks = drive_locks
        self.rng = rng
        self.stop = stop
        self.peek_path = peek               # a path to another client's drive, reads only
        self.after_failure = None           # e.g. drain the CAN link of late frames
        # --inject: defects this client makes once on purpose, to show that
        # the checks catch them
        self.inject = set()

    # -- the loop -------------------------------------------------------

    def run(self):
        ops, weights = zip(*self.OPERATIONS)
        while not self.stop.is_set():
            self.gate.enter()
            try:
                drive = self.rng.choice(sorted(self.paths))
                with self.drive_locks[drive]:
                    model = self.models[drive]
                    if model.verify_pending:
                        self.verify(drive)
                    else:
                        op = self.rng.choices(ops, weights)[0]
                        if "wrong-value" in self.inject:
                            op = "write_read"
                        elif "double-move" in self.inject:
                            op = "move_by"
                        self.stats.trace("%s: drive %d: %s" % (self.name, drive, op))
                        getattr(self, op)(drive)
            except LinkDown as err:
                self.stats.failure(self.name, "link down: %s" % str(err)[:40], True)
                self.models[drive].power_lost()
                time.sleep(0.2)
            except Unrecovered as err:
                self.stats.defect("%s: %s" % (self.name, err))
                time.sleep(1.0)
            finally:
                self.gate.leave()

    # -- answers that a fault may take -----------------------------------

    def failed(self, drive, cause, since):
        """A call that a fault may have taken (counted by cause); any other
        error is a defect: the soak sends only what a drive accepts."""
        in_fault = self.faults.overlapped(since, time.monotonic(), drive)
        self.stats.failure(self.name, cause, in_fault)
        if not cause.startswith(FAULT_CAUSES):
            self.stats.defect("%s: drive %d answered %r" % (self.name, drive, cause))
        return in_fault

    def settled(self, drive, call, what):
        """@call() until it answers: after each failure, wait for the fault
        window to end (the truth is read after it)."""
        began = time.monotonic()
        while True:
            started = time.monotonic()
            try:
                return call()
            except NoAnswer as err:
                self.failed(drive, err.cause, started)
            if time.monotonic() - began > RETRY_FOR:
                raise Unrecovered("drive %d: %s unanswered for %.0f s" % (drive, what, RETRY_FOR))
            self.faults.wait_quiet(drive, RETRY_FOR)
            if self.after_failure:
                # what a fault held back comes out when it ends: not an answer
                self.after_failure()

    def read(self, drive, name, kind):
        path = self.paths[drive]
        return self.settled(drive, lambda: path.read(name, kind), "r " + name)

    def state(self, drive):
        return self.settled(drive, self.paths[drive].state, "its state")

    def send(self, drive, call):
        """A silent command; False when it was answered with an error."""
        started = time.monotonic()
        try:
            call()
            return True
        except NoAnswer as err:
            self.failed(drive, err.cause, started)
            return False

    # -- operations --------------------------------------------------------

    def verify(self, drive):
        """After power came back: every property holds one of the values its
        NVM may hold; that one is now both live and saved."""
        model = self.models[drive]
        for name, kind, _ in PROPERTIES:
            got = self.read(drive, name, kind)
            possible = model.saved.get(name)
            if possible is not None and not any(same_value(kind, got, v) for v in possible):
                self.stats.defect("%s: drive %d lost its NVM: %s reads %s after power came "
                                  "back, saved was %s" % (self.name, drive, name, shown(got),
                                                          " or ".join(map(shown, possible))))
            model.live[name] = got
            model.saved[name] = [got]
        model.verify_pending = False
        self.stats.event("NVM checked after power came back (drive reads)")

    def write_read(self, drive, name=None, value=None):
        model = self.models[drive]
        path = self.paths[drive]
        if name is None:
            name, kind, _ = self.rng.choice(PROPERTIES)
        kind = next(k for n, k, _ in PROPERTIES if n == name)
        old = model.live[name]
        new = value
        while new is None or same_value(kind, new, old):
            new = random_value(self.rng, kind)
        sent = new
        if "wrong-value" in self.inject:
            self.inject.discard("wrong-value")
            while same_value(kind, sent, new) or same_value(kind, sent, old):
                sent = random_value(self.rng, kind)
        began = time.monotonic()
        delivered = self.send(drive, lambda: path.write(name, kind, sent))
        got = self.read(drive, name, kind)
        ended = time.monotonic()
        if same_value(kind, got, new):
            model.live[name] = new
            self.stats.event("writes read back")
        elif same_value(kind, got, old) and (
                not delivered or self.faults.overlapped(began, ended, drive)):
            model.live[name] = old
            self.stats.event("writes lost in a fault window (old value read back)")
        else:
            self.stats.defect("%s: drive %d: w %s %s then r gave %s (it held %s)" %
                              (self.name, drive, name, shown(new), shown(got), shown(old)))
            model.live[name] = got
        return new

    def save(self, drive):
        model = self.models[drive]
        path = self.paths[drive]
        began = time.monotonic()
        delivered = self.send(drive, path.save)
        # a read of the same drive after the save: its frames are handled in
        # order, so the save is done (or lost) when the reply comes
        name, kind, _ = self.rng.choice(PROPERTIES)
        self.read(drive, name, kind)
        sure = delivered and not self.faults.overlapped(began, time.monotonic(), drive)
        for name, kind, _ in PROPERTIES:
            value = model.live[name]
            if sure:
                model.saved[name] = [value]
            elif not any(same_value(kind, value, v) for v in model.saved[name]):
                model.saved[name] = model.saved[name] + [value]
        self.stats.event("saves (ss)" if sure else "saves a fault may have taken")

    def peek(self, drive):
        if self.peek_path is None:
            name, kind, _ = self.rng.choice(PROPERTIES)
            got = self.read(drive, name, kind)
            if not same_value(kind, got, self.models[drive].live[name]):
                self.stats.defect("%s: drive %d: r %s gave %s, it holds %s" %
                                  (self.name, drive, name, shown(got),
                                   shown(self.models[drive].live[name])))
            return
        # a read of another client's drive: its answer is matched among
        # the bridge's frames to and from that drive
        started = time.monotonic()
        try:
            self.peek_path.state()
        except NoAnswer as err:
            self.failed(self.peek_path.drive, err.cause, started)

    def move_to(self, drive):
        self.move(drive, relative=False)

    def move_by(self, drive):
        self.move(drive, relative=True)

    def move(self, drive, relative):
        model = self.models[drive]
        path = self.paths[drive]
        start, done = self.state(drive)
        waited = time.monotonic()
        while not done and time.monotonic() - waited < 5.0:
            time.sleep(0.05)
            start, done = self.state(drive)
        if not done:
            self.stats.defect("%s: drive %d: trajectory_done 0 at rest for 5 s" % (self.name, drive))
            return
        if model.landing is not None and abs(start - model.landing) > LANDING_TOLERANCE:
            self.stats.defect("%s: drive %d moved by itself: landed at %.3f, now at %.3f"
                              % (self.name, drive, model.landing, start))
        distance = self.rng.uniform(10.0, 40.0) * (-1 if start > 180 else 1 if start < -180
                                                   else self.rng.choice((-1, 1)))
        distance = f32(round(distance, 2))
        target = start + distance
        self.stats.trace("%s: drive %d: from %.3f by %.2f to %.3f" % (self.name, drive, start, distance, target))
        began = time.monotonic()
        if relative:
            planned = math.ceil(trapezoid_time(distance, MOVE_VEL, MOVE_ACC) * 130) / 100.0
            sent = self.send(drive, lambda: path.move_by(distance, planned, MOVE_ACC))
            if "double-move" in self.inject:
                # as a client that resends a move it thinks was lost
                self.inject.discard("double-move")
                time.sleep(planned + 0.2)
                self.send(drive, lambda: path.move_by(distance, planned, MOVE_ACC))
        else:
            planned = trapezoid_time(distance, MOVE_VEL, MOVE_ACC)
            sent = self.send(drive, lambda: path.move_to(target, MOVE_VEL, MOVE_ACC))
        time.sleep(planned * 0.9)
        deadline = time.monotonic() + planned + 5.0
        position, done = self.state(drive)
        while not done and time.monotonic() < deadline:
            time.sleep(0.03)
            position, done = self.state(drive)
        time.sleep(SETTLE)
        position, done = self.state(drive)
        ended = time.monotonic()
        model.landing = position
        error = position - target
        if done and abs(error) <= LANDING_TOLERANCE:
            self.stats.landed(error)
            self.stats.event("moves landed (%s)" % ("relative" if relative else "absolute"))
        elif abs(position - start) <= LANDING_TOLERANCE and (
                not sent or self.faults.overlapped(began, ended, drive)):
            self.stats.event("moves lost in a fault window (the drive stayed)")
        elif relative and abs(position - (start + 2 * distance)) <= LANDING_TOLERANCE:
            self.stats.defect("%s: drive %d ran a relative move twice: %.3f + %.2f ended at %.3f"
                              % (self.name, drive, start, distance, position))
        else:
            self.stats.defect("%s: drive %d: a move from %.3f to %.3f ended at %.3f (done %d)"
                              % (self.name, drive, start, target, position, done))
