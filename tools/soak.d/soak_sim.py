"""daran-sim as the soak runs it: started with its pseudo-terminals and an
NVM folder, its stdin for directives, its stdout and stderr drained so it
never blocks, killed (SIGKILL, the power cut) or stopped (SIGTERM), and its
RSS and open file descriptors read from /proc."""
import collections
import os
import signal
import subprocess
import threading

# The topology (docs/reliability.md): drive 1 is the vendor-like ASCII
# client's and the gateway of the bridge, drives 2 and 3 are reached
# through it, drive 4 by the CAN client over the slcan adapter.
DRIVES = 4


class SimDied(Exception):
    """daran-sim ended or its pseudo-terminal went away."""


class Sim:
    def __init__(self, binary, nvm_dir, log_path):
        self.binary = binary
        self.nvm_dir = nvm_dir
        self.log_path = log_path
        self.proc = None
        self.paths = []
        self.generation = 0
        self.stderr_tail = collections.deque(maxlen=50)
        self.stderr_lines = 0
        self.sanitizer_reports = []
        self.console_bytes = 0
        self._stdin_lock = threading.Lock()

    def start(self):
        """A new daran-sim on the same NVM folder; its ASCII and slcan paths."""
        self.proc = subprocess.Popen(
            [self.binary, "--drives", str(DRIVES), "--pty", "--slcan", "--bridge",
             "--nvm", self.nvm_dir],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.paths = [self.proc.stdout.readline().decode().strip() for _ in range(2)]
        if not all(p.startswith("/dev/") for p in self.paths):
            self.kill()
            raise SimDied("daran-sim printed no pty paths: %r" % self.paths)
        self.generation += 1
        threading.Thread(target=self._drain_stdout, args=(self.proc,), daemon=True).start()
        threading.Thread(target=self._drain_stderr, args=(self.proc,), daemon=True).start()
        return self.paths

    def _drain_stdout(self, proc):
        # the console's `can ...` lines: every frame on the bus; only counted
        fd = proc.stdout.fileno()
        while True:
            try:
                chunk = os.read(fd, 65536)
            except OSError:
                return
            if not chunk:
                return
            self.console_bytes += len(chunk)

    def _drain_stderr(self, proc):
        with open(self.log_path, "a", encoding="utf-8") as log:
            try:
                for raw in proc.stderr:
                    line = raw.decode(errors="replace").rstrip("\n")
                    self.stderr_lines += 1
                    self.stderr_tail.append(line)
                    if "runtime error:" in line or "Sanitizer" in line:
                        # a Debug + ASan/UBSan build (the host preset) says so
                        self.sanitizer_reports.append("pid %d: %s" % (proc.pid, line))
                    log.write("[pid %d] %s\n" % (proc.pid, line))
                    log.flush()
            except (OSError, ValueError):
                return

    @property
    def pid(self):
        return self.proc.pid if self.proc else None

    def alive(self):
        return self.proc is not None and self.proc.poll() is None

    def directive(self, line):
        with self._stdin_lock:
            try:
                self.proc.stdin.write((line + "\n").encode())
                self.proc.stdin.flush()
            except (OSError, ValueError) as err:
                raise SimDied("stdin: %s" % err)

    def kill(self):
        """SIGKILL: the power cut of the whole bench. Its exit status."""
        if self.proc is None:
            return None
        if self.proc.poll() is None:
            os.kill(self.proc.pid, signal.SIGKILL)
        self.proc.wait()
        self._close_pipes()
        return self.proc.returncode

    def stop(self):
        """SIGTERM (SIGKILL 5 s later if it is still there); True when it died
        of SIGTERM, as daran-sim should."""
        if self.proc is None:
            return True
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self._close_pipes()
        return self.proc.returncode in (-signal.SIGTERM, 128 + signal.SIGTERM)

    def _close_pipes(self):
        for stream in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            try:
                stream.close()
            except (OSError, ValueError):
                pass

    def resources(self):
        """(RSS in kB, open fds) of the running daran-sim, or None."""
        if not self.alive():
            return None
        try:
            with open("/proc/%d/status" % self.proc.pid, encoding="ascii") as status:
                rss = next(int(line.split()[1]) for line in status if line.startswith("VmRSS:"))
            fds = len(os.listdir("/proc/%d/fd" % self.proc.pid))
        except (OSError, StopIteration, ValueError):
            return None
        return rss, fds

