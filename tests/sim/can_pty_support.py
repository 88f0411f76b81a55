"""What the CAN pty tests share: a module or a skip (exit 77), daran-sim
started with its adapters, the pseudo-terminal paths it prints, its stdout
(the console's `can ...` lines) read in the background so it never fills,
little-endian helpers, the end by SIGTERM and the verdict. Used by
pty_slcan.py, pty_usbcan.py and pty_can_links.py (stdlib only)."""
import importlib
import os
import struct
import subprocess
import sys
import threading


def require(module, package):
    """@module imported, or the test skipped (exit 77) when @package is
    not installed."""
    try:
        return importlib.import_module(module)
    except ImportError:
        print("%s is not installed: skipped" % package)
        sys.exit(77)


def end_process(proc):
    """SIGTERM to @proc (a subprocess.Popen) unless it has ended, SIGKILL
    when it is still there 5 s later; its exit status."""
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    return proc.returncode


class Sim:
    """daran-sim with @options; paths holds the pty paths it printed, in
    order (the ASCII link's first with --pty, then --slcan's, --usbcan's)."""

    def __init__(self, sim_path, options, ptys):
        self.proc = subprocess.Popen([sim_path] + options, stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.paths = [self.proc.stdout.readline().decode().strip() for _ in range(ptys)]
        self.console = []
        self.errors = []
        threading.Thread(target=self._drain, args=(self.proc.stdout, self.console),
                         daemon=True).start()
        threading.Thread(target=self._drain, args=(self.proc.stderr, self.errors),
                         daemon=True).start()

    @staticmethod
    def _drain(stream, into):
        for line in stream:
            into.append(line.decode(errors="replace").rstrip("\n"))

    def directive(self, line):
        """A line on daran-sim's stdin (a directive, or an ASCII line)."""
        self.proc.stdin.write((line + "\n").encode())
        self.proc.stdin.flush()

    def stop(self):
        """SIGTERM; True when daran-sim died of it, as it should. Its pipes
        are closed."""
        end_process(self.proc)
        for stream in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            try:
                stream.close()
            except OSError:
                pass
        return self.proc.returncode in (-15, 143)


def f32(data, at=0):
    return struct.unpack_from("<f", bytes(data), at)[0]


def u32(data, at=0):
    return struct.unpack_from("<I", bytes(data), at)[0]


# Frames of the vendor's python-can recording (../shared/recordings/
# vendor-can-socketcan.txt): get_id() broadcast, read pos_estimate, fast read.
GET_ID = (0x01E, bytes.fromhex("1979030000000000"))
READ_POS = bytes.fromhex("7794000000000000")  # address 0x9477, type f32
FAST_READ = bytes(8)
# set_angle(id, 90, 0, 10, 0): 0x019 at the node, 90.0 f32, bandwidth 10 x 100
T_90 = bytes.fromhex("0000b4420000e803")


def run(name, options, ptys, checks):
    """A whole test: daran-sim (argv[1]) started with @options, printing
    @ptys paths; @checks(sim, failures) run on it; daran-sim stopped by
    SIGTERM. Returns the exit status (77: no pseudo-terminals here)."""
    if not os.path.exists("/dev/ptmx"):
        print("no /dev/ptmx on this machine: skipped")
        return 77
    sim = Sim(sys.argv[1], options, ptys)
    failures = []
    try:
        if all(p.startswith("/dev/") for p in sim.paths):
            checks(sim, failures)
        else:
            failures.append("no pty paths on stdout: %r" % sim.paths)
    finally:
        stopped = sim.stop()
    for failure in failures:
        print("FAIL:", failure)
    if not stopped:
        print("FAIL: daran-sim did not die of SIGTERM")
        return 1
    print("%s: %s" % (name, "all checks passed" if not failures else "failed"))
    return 1 if failures else 0
