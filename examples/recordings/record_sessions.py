#!/usr/bin/python3
"""Records the three example sessions of examples/recordings/ with
`daran-sim --record`: a client program (this script) drives daran-sim in
lock-step, reads the replies it asks for, and decides what to send next, as a
host application would.

  pick-and-place.txt    one drive; a pick-and-place arm streams `t` at 500 Hz
                        for 2 s (minimum-jerk moves between a few points),
                        polling `f 1` every 50 ms
  multi-drive-sync.txt  three drives; synchronised moves: `ms` x 3 + `mq 0 0`,
                        then `trajectory_done` polled on each drive until all
                        three have arrived
  tuning.txt            one drive; a tuning session: read the gains, write
                        pos_gain / vel_gain / vel_integrator_gain steps, a
                        step move with `q` for each, its response polled
                        with `f 1` every 10 ms

usage: record_sessions.py DARAN_SIM OUT_DIR [EXPECTED_DIR]
Writes OUT_DIR/NAME.txt and, with EXPECTED_DIR, the drives' replies of the
run as EXPECTED_DIR/NAME.expected (what tools/replay must give back).
Exits 1 if any reply is an error: these are sessions a client ran cleanly.
"""
import os
import subprocess
import sys


def fmt(x, digits):
    """A decimal as a Python client prints a rounded float: no trailing zeros."""
    text = f"{x:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


class Link:
    """daran-sim in lock-step, recording; replies read line by line."""

    def __init__(self, sim, record, drives):
        self.proc = subprocess.Popen(
            [sim, "--drives", str(drives), "--record", record],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.replies = bytearray()
        self.errors = []

    def send(self, line):
        """A line no drive answers (motion, write, preset)."""
        self.proc.stdin.write(line.encode() + b"\n")

    def ask(self, line, replies=1):
        """A query: returns the reply lines (without their newline)."""
        self.send(line)
        self.proc.stdin.flush()
        got = []
        for _ in range(replies):
            reply = self.proc.stdout.readline()
            if not reply:
                raise RuntimeError(f"daran-sim ended while answering {line!r}")
            self.replies += reply
            text = reply.decode().rstrip("\n")
            if text.startswith("error"):
                self.errors.append(f"{line!r} -> {text!r}")
            got.append(text)
        return got

    def advance(self, seconds):
        self.proc.stdin.write(f"!advance {seconds}\n".encode())

    def close(self):
        self.proc.stdin.close()
        rest = self.proc.stdout.read()  # anything unasked for is a mistake
        self.replies += rest
        if rest:
            self.errors.append(f"unexpected replies: {rest[:200]!r}")
        if self.proc.wait() != 0:
            self.errors.append(f"daran-sim exit status {self.proc.returncode}")
        return bytes(self.replies)


def min_jerk(x0, x1, s):
    """Position and velocity factor of a minimum-jerk move at s = t/T in [0, 1]."""
    pos = x0 + (x1 - x0) * (10 * s**3 - 15 * s**4 + 6 * s**5)
    vel = (x1 - x0) * (30 * s**2 - 60 * s**3 + 30 * s**4)  # times 1/T
    return pos, vel


def pick_and_place(link):
    """Pick at 0 deg, place at 120, back via a via point; dwells at each
    end. 1000 `t` lines, 2 ms apart; `f 1` every 50 ms."""
    link.ask("r axis0.config.can_node_id ")
    link.ask("e 1 ")
    link.ask("f 1 ")
    # (target deg, move time s, dwell s): 2.000 s in all
    plan = [(120.0, 0.45, 0.10), (120.0, 0.0, 0.05), (45.0, 0.30, 0.05),
            (-30.0, 0.35, 0.10), (0.0, 0.40, 0.20)]
    period = 0.002
    samples = []
    x = 0.0
    for target, move, dwell in plan:
        n_move = round(move / period)
        for k in range(1, n_move + 1):
            pos, vel = min_jerk(x, target, k / n_move)
            samples.append((pos, vel / move * 60.0 / 360.0))  # deg/s -> r/min
        samples += [(target, 0.0)] * round(dwell / period)
        x = target
    assert len(samples) == 1000, len(samples)
    for k, (pos, vel_rpm) in enumerate(samples):
        # the first line sets the input filter bandwidth for the stream
        link.send(f"t 1 {fmt(pos, 3)} {fmt(vel_rpm, 2)} 200 " if k == 0
                  else f"t 1 {fmt(pos, 3)} {fmt(vel_rpm, 2)} ")
        if k % 25 == 24:
            link.ask("f 1 ")
        link.advance(period)
    link.advance(0.2)
    link.ask("f 1 ")
    link.ask("e 1 ")


def multi_drive_sync(link):
    """Three synchronised moves; `trajectory_done` polled every 50 ms."""
    for drive in (1, 2, 3):
        link.ask(f"e {drive} ")
    moves = [  # per drive target deg; duration s; acceleration (r/min)/s
        ((90.0, -45.0, 180.0), 1.5, 60.0),
        ((0.0, 45.0, 90.0), 1.2, 80.0),
        ((-60.0, 10.0, 45.0), 1.0, 60.0),
        ((0.0, 0.0, 0.0), 2.0, 40.0),
    ]  # every one feasible: distance <= A T^2 / 4 with A = 6 acc deg/s^2
    for targets, duration, acc in moves:
        for drive, target in enumerate(targets, 1):
            link.send(f"ms {drive} {fmt(target, 3)} {fmt(duration, 3)} {fmt(acc, 3)} ")
        link.send("mq 0 0 ")
        polls = 0
        while True:
            link.advance(0.05)
            polls += 1
            done = [link.ask(f"r axis{d}.controller.trajectory_done ")[0] for d in (1, 2, 3)]
            if done == ["1", "1", "1"]:
                break
            if polls > 200:
                raise RuntimeError("the synchronised move never finished")
        for drive in (1, 2, 3):
            link.ask(f"f {drive} ")


def tuning(link):
    """Read the gains, then for each gain set: write it, read it back, step
    +10 deg and back with `q`, watching the response every 10 ms."""
    gains = ("pos_gain", "vel_gain", "vel_integrator_gain")
    prefix = "axis1.controller.config."
    link.ask("i 1 ")
    for g in gains:
        link.ask(f"r {prefix}{g} ")
    sets = [(20.0, 0.16, 0.8), (30.0, 0.16, 0.8), (30.0, 0.24, 0.8),
            (30.0, 0.24, 1.6), (45.0, 0.3, 2.0), (20.0, 0.16, 0.8)]
    position = 0.0
    for values in sets:
        for g, v in zip(gains, values):
            link.send(f"w {prefix}{g} {fmt(v, 4)} ")
        for g in gains:
            link.ask(f"r {prefix}{g} ")
        for step in (10.0, -10.0):
            position += step
            link.send(f"q 1 {fmt(position, 3)} 300 3000 ")
            for _ in range(40):
                link.advance(0.01)
                link.ask("f 1 ")
        link.ask("r axis1.output_shaft.torque_estimate ")
    link.ask("e 1 ")
    link.send("ss 1 ")


def describe(record, doc):
    """Put what the session is above daran-sim's own header lines."""
    with open(record, "rb") as f:
        data = f.read()
    head = "# " + doc + " Recorded by examples/recordings/record_sessions.py."
    lines, line = [], ""
    for word in head.split(" "):
        if line and len(line) + 1 + len(word) > 88:
            lines.append(line)
            line = "#"
        line += (" " if line else "") + word
    lines.append(line)
    with open(record, "wb") as f:
        f.write("\n".join(lines).encode() + b"\n" + data)


SESSIONS = [
    ("pick-and-place", 1, pick_and_place,
     "A pick-and-place arm on one drive streams `t` at 500 Hz for 2 s: minimum-jerk "
     "moves 0 -> 120 -> 45 -> -30 -> 0 deg with dwells, `f 1` polled every 50 ms."),
    ("multi-drive-sync", 3, multi_drive_sync,
     "Four synchronised moves of three drives: `ms` x 3 + `mq 0 0`, then "
     "`trajectory_done` of each drive polled every 50 ms until all three are done, "
     "then `f` of each."),
    ("tuning", 1, tuning,
     "A tuning session on one drive: the gains read, then six sets of pos_gain / "
     "vel_gain / vel_integrator_gain written and read back, each tried with a 10 deg "
     "step move (`q`) and back, the response polled with `f 1` every 10 ms."),
]


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    sim, out_dir = sys.argv[1], sys.argv[2]
    expected_dir = sys.argv[3] if len(sys.argv) == 4 else None
    status = 0
    for name, drives, session, description in SESSIONS:
        record = os.path.join(out_dir, name + ".txt")
        link = Link(sim, record, drives)
        session(link)
        replies = link.close()
        if expected_dir:
            with open(os.path.join(expected_dir, name + ".expected"), "wb") as f:
                f.write(replies)
        for e in link.errors:
            print(f"{name}: {e}", file=sys.stderr)
            status = 1
        describe(record, description)
        lines = replies.count(b"\n")
        print(f"{name}: {os.path.getsize(record)} bytes recorded, {lines} reply lines")
    return status


if __name__ == "__main__":
    sys.exit(main())
