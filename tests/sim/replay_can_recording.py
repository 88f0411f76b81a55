#!/usr/bin/python3
"""The vendor's python-can recording replayed into `daran-sim --can --drives 3`
in lock-step: each recorded frame sent by the console's node (`!can`), then
3 ms of simulated time; what the drives send in those 3 ms is that frame's
answer (the console shows every frame as a `can` line with its time).

Two runs, as the recording's harness kept its fake drives (node ids kept,
`enable_reply_state` 1 in the second pass only), with no frame on the bus
but the recorded ones and the checks':

- as recorded: each 0x01E read is answered by every drive it addresses
  (node 0: all three, lowest id first, C8) with the right id, code,
  address and the property's type code (include/daran_properties.h; a
  get_id() answer carries the drive's id), a fast read by a status frame
  of that node, a motion or preset by a status frame when that drive's
  enable_reply_state is 1; nothing else is sent, for any other frame.
- witness: every drive has enable_reply_state 1 throughout, so every motion
  and preset the drives accept is answered by a status frame of each
  drive it addresses (a frame refused by the contract's section 4 gets
  none, C10); each write is read back from every drive it addresses and
  holds the written value, except the writes the contract refuses:
  set_id()'s node id 0 (C14: the ids stay) and set_mode()'s closed loop
  while the recording has e-stopped the drives (C30: requested_state stays
  as it was, not 8); after each system command a
  fast read finds every addressed drive answering, e-stopped (E set) after
  0x06 and clear after 0x04.

Both runs: exit status 0 and nothing on stderr (no `!can` refused, no frame
lost or unsent). The values are the simulated drives' own, so they are not
compared with the recording's responder's, except as said.

The recording is read from the repository's copy, the C table
tests/unit/can_recording_data.h (kept equal to the shared recording by
unit_can_recording_data_is_current), or from the recording itself when
given a .txt file (through tests/unit/gen_can_recording_data.py).

usage: replay_can_recording.py DARAN_SIM RECORDING PROPERTIES_H [--session FILE]
  (--session: also write the as-recorded session there, to read or replay)
"""
import os
import re
import struct
import subprocess
import sys

STEP_S = 0.003  # after each frame: its answers end within 1.5 ms at 1 kHz
DRIVES = (1, 2, 3)
TYPE_CODES = {"F32": 0, "U32": 3, "BOOL": 3, "S32": 4}
CAN_NODE_ID = 31001
REQUESTED_STATE = 30003
CLOSED_LOOP = 8
ENABLE_REPLY_STATE = 31214
READ, WRITE, SYSTEM, PRESET = 0x1E, 0x1F, 0x08, 0x0C
MOTIONS = (PRESET, 0x19, 0x1A, 0x1B, 0x1C, 0x1D)
REBOOT, CLEAR_ERRORS, ESTOP = 0x03, 0x04, 0x06


def recording(path):
    """(call, pass, id, dlc, data) of every recorded frame, in order."""
    if path.endswith(".txt"):
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "unit"))
        import gen_can_recording_data
        return [(call, p, i, dlc, bytes(data))
                for call, p, i, dlc, data in gen_can_recording_data.frames(path)]
    with open(path, encoding="utf-8") as f:
        text = f.read()
    rows = re.findall(r'\{"((?:[^"\\]|\\.)*)", (\d), 0x([0-9A-F]+), (\d), \{([^}]*)\}\}', text)
    claimed = int(re.search(r"#define CAN_RECORDING_FRAMES (\d+)u", text).group(1))
    if len(rows) != claimed:
        sys.exit("%s: %d frames read, %d claimed" % (path, len(rows), claimed))
    return [(call, int(p), int(i, 16), int(dlc), bytes(int(b, 16) for b in data.split(", ")))
            for call, p, i, dlc, data in rows]


def type_codes(properties_h):
    """{CAN address: type code} of the property list."""
    with open(properties_h, encoding="utf-8") as f:
        rows = re.findall(r'X\(\w+,\s*"[^"]*",\s*\w+,\s*(\w+),\s*\w+,\s*\w+,\s*"[^"]*",\s*(\d+)\)',
                          f.read())
    return {int(address): TYPE_CODES[kind] for kind, address in rows if int(address) != 0}


def u16(data, at):
    return struct.unpack_from("<H", data, at)[0]


def u32(data, at):
    return struct.unpack_from("<I", data, at)[0]


def value_of(type_code, bits):
    """A property value's number from its 4 bytes (little-endian) and type code."""
    if type_code == 0:
        return struct.unpack("<f", struct.pack("<I", bits))[0]
    if type_code == 1:
        return bits & 0xFFFF
    if type_code == 2:
        return struct.unpack("<h", struct.pack("<H", bits & 0xFFFF))[0]
    if type_code == 4:
        return struct.unpack("<i", struct.pack("<I", bits))[0]
    return bits


def can_directive(ident, data):
    return "!can %03X %s" % (ident, " ".join("%02X" % b for b in data)) if data else "!can %03X" % ident


def status_of(node):
    return ("status", node)


def read_reply(node, address, type_code):
    return ("read", node, address, type_code)


class Session:
    """The lines of a lock-step session, and what each frame's 3 ms should
    hold: steps[k] = (what, expected answers, value checks) for the k-th
    frame sent."""

    def __init__(self):
        self.lines = []
        self.steps = []

    def line(self, text):
        self.lines.append(text)

    def frame(self, ident, data, what, expected, checks=()):
        self.lines.append(can_directive(ident, data))
        self.lines.append("!advance %g" % STEP_S)
        self.steps.append((what, expected, list(checks)))


class Drives:
    """What the harness knows of the three drives (index 0..2 is drive
    1..3): their node ids, their enable_reply_state, their e-stop flag."""

    def __init__(self, reply_state):
        self.ids = list(DRIVES)
        self.reply_state = [reply_state] * len(DRIVES)
        self.estopped = [False] * len(DRIVES)

    def copy(self):
        other = Drives(0)
        other.ids, other.reply_state = list(self.ids), list(self.reply_state)
        other.estopped = list(self.estopped)
        return other

    def addressed(self, node):
        """Indexes of the drives a frame at @node reaches, in id order."""
        found = [k for k, ident in enumerate(self.ids) if node in (0, ident)]
        return sorted(found, key=lambda k: self.ids[k])


def expected_answers(frame, drives, types):
    """What the drives send for one recorded frame (docs: can.md 2.2)."""
    ident, dlc, data = frame
    node, code = ident >> 5, ident & 0x1F
    if dlc != 8:
        return [], []
    reached = drives.addressed(node)
    if code == READ and u16(data, 0) == 0:
        return [status_of(drives.ids[k]) for k in reached], []
    if code == READ:
        address = u16(data, 0)
        if address not in types:
            return [], []
        checks = []
        if address == CAN_NODE_ID:
            checks = [(drives.ids[k], "equals", drives.ids[k]) for k in reached]
        return [read_reply(drives.ids[k], address, types[address]) for k in reached], checks
    if code in MOTIONS:
        return [status_of(drives.ids[k]) for k in reached if drives.reply_state[k]], []
    return [], []


def refused_write(frame, drives, k):
    """Whether the contract has drive @k refuse a recorded write: set_id()'s
    node id 0 (C14, can.md 6.6), closed loop requested while e-stopped (C30)."""
    _ident, _dlc, data = frame
    address, value = u16(data, 0), u32(data, 4)
    return (address == CAN_NODE_ID and value == 0) or \
        (address == REQUESTED_STATE and value == CLOSED_LOOP and drives.estopped[k])


def apply_frame(frame, drives):
    """What a frame the drives accept changes in what the harness knows."""
    ident, dlc, data = frame
    code = ident & 0x1F
    if dlc != 8 or code not in (WRITE, SYSTEM):
        return
    for k in drives.addressed(ident >> 5):
        if code == SYSTEM and u32(data, 0) in (REBOOT, CLEAR_ERRORS, ESTOP):
            drives.estopped[k] = u32(data, 0) == ESTOP
        elif code == WRITE and not refused_write(frame, drives, k):
            if u16(data, 0) == CAN_NODE_ID:
                drives.ids[k] = u32(data, 4)
            elif u16(data, 0) == ENABLE_REPLY_STATE:
                drives.reply_state[k] = 1 if u32(data, 4) else 0


def witness_write(session, frame, before, types):
    """Read the written address back from each drive the write reached:
    the written value, or for a refused write its old value (a node id) or
    anything but the written one. Returns the refusals."""
    ident, _dlc, data = frame
    address, type_code, bits = u16(data, 0), u16(data, 2), u32(data, 4)
    refusals = 0
    for k in before.addressed(ident >> 5):
        node = before.ids[k]
        check = (node, "equals", value_of(type_code, bits))
        if refused_write(frame, before, k):
            refusals += 1
            check = (node, "equals", node) if address == CAN_NODE_ID else \
                (node, "differs", value_of(type_code, bits))
        elif address == CAN_NODE_ID:
            node = bits  # the drive answers with its new id
            check = (node, "equals", node)
        session.frame(node << 5 | READ, struct.pack("<HHI", address, 0, 0),
                      "read back %d from node %d" % (address, node),
                      [read_reply(node, address, types[address])], [check])
    return refusals


def witness_system(session, frame, drives):
    """A fast read of each drive a system command reached: it answers, and
    after an e-stop its E bit is set, after a clear it is not."""
    ident, _dlc, data = frame
    subcode = u32(data, 0)
    for k in drives.addressed(ident >> 5):
        node = drives.ids[k]
        checks = []
        if subcode == ESTOP:
            checks = [(node, "error", True)]
        elif subcode == CLEAR_ERRORS:
            checks = [(node, "error", False)]
        session.frame(node << 5 | READ, bytes(8), "fast read of node %d after sub-code 0x%02X"
                      % (node, subcode), [status_of(node)], checks)


def build(frames, types, witness):
    """The session of one run (witness: with the acceptance checks)."""
    session = Session()
    session.refusals = 0
    drives = Drives(1 if witness else 0)
    if witness:
        session.line("w axis0.config.extra_setting.enable_reply_state 1")
    current_pass = 1
    for index, (call, recording_pass, ident, dlc, data) in enumerate(frames):
        if recording_pass != current_pass and not witness:
            # the harness's drives: enable_reply_state 1 in pass 2 only
            state = 1 if recording_pass == 2 else 0
            session.line("w axis0.config.extra_setting.enable_reply_state %d" % state)
            drives.reply_state = [state] * len(DRIVES)
        current_pass = recording_pass
        frame = (ident, dlc, data)
        before = drives.copy()
        expected, checks = expected_answers(frame, drives, types)
        session.frame(ident, data[:dlc], call, expected, checks)
        apply_frame(frame, drives)
        code = ident & 0x1F
        if witness and dlc == 8 and code == WRITE and u16(data, 0) in types:
            session.refusals += witness_write(session, frame, before, types)
        if witness and dlc == 8 and code == SYSTEM:
            witness_system(session, frame, drives)
        last_of_call = index + 1 == len(frames) or frames[index + 1][0] != call
        if last_of_call:
            # the recording's responder kept its node ids
            for k, ident_now in enumerate(drives.ids):
                if ident_now != DRIVES[k]:
                    session.line("w axis%d.config.can_node_id %d" % (ident_now, DRIVES[k]))
                    drives.ids[k] = DRIVES[k]
    return session


def run(sim, session):
    """daran-sim on the session: (exit status, can lines, other stdout, stderr)."""
    text = "\n".join(session.lines) + "\n"
    proc = subprocess.run([sim, "--can", "--drives", "3"], input=text.encode(),
                          capture_output=True, timeout=120)
    frames, other = [], []
    for line in proc.stdout.decode(errors="replace").splitlines():
        words = line.split()
        if words[:1] == ["can"] and len(words) >= 4:
            frames.append((float(words[1]), int(words[2], 16),
                           bytes(int(b, 16) for b in words[4:])))
        else:
            other.append(line)
    return proc.returncode, frames, other, proc.stderr.decode(errors="replace")


def answer_key(ident, data):
    node, code = ident >> 5, ident & 0x1F
    if code == READ and len(data) == 8:
        return read_reply(node, u16(data, 0), u16(data, 2))
    if code & 1 and code < 0x08:
        return status_of(node)
    return ("other", ident)


def check_value(check, answers, failures, what):
    node, kind, want = check
    for ident, data in answers:
        if ident >> 5 != node:
            continue
        if kind == "error":
            if bool(ident & 0x04) != want:
                failures.append("%s: node %d's E bit is %d" % (what, node, (ident >> 2) & 1))
            return
        got = value_of(u16(data, 2), u32(data, 4))
        if (got == want) != (kind == "equals"):
            failures.append("%s: node %d answered %r, want %s %r" % (what, node, got,
                            "" if kind == "equals" else "anything but", want))
        return


def verify(name, session, result, failures):
    """Each frame's 3 ms against what it should hold. Returns counts."""
    status, frames, other, errors = result
    if status != 0 or errors:
        failures.append("%s: exit status %d, stderr %r" % (name, status, errors[:400]))
    if other:
        failures.append("%s: stdout lines that are not frames: %r" % (name, other[:5]))
    counts = {"steps": 0, "answered": 0, "answers": 0}
    for k, (what, expected, checks) in enumerate(session.steps):
        start, end = k * STEP_S, (k + 1) * STEP_S
        answers = [(ident, data) for t, ident, data in frames if start < t <= end + 1e-9]
        got = [answer_key(ident, data) for ident, data in answers]
        counts["steps"] += 1
        counts["answered"] += 1 if expected else 0
        counts["answers"] += len(got)
        if got != expected:
            failures.append("%s, frame %d (%s): answered %r, want %r" % (name, k + 1, what, got, expected))
            continue
        for check in checks:
            check_value(check, answers, failures, "%s, frame %d (%s)" % (name, k + 1, what))
    late = [f for f in frames if f[0] > len(session.steps) * STEP_S + 1e-9]
    if late:
        failures.append("%s: frames after the last step: %r" % (name, late[:3]))
    return counts


def main(argv):
    if len(argv) not in (4, 6) or (len(argv) == 6 and argv[4] != "--session"):
        sys.exit(__doc__)
    sim, recorded, properties_h = argv[1:4]
    frames = recording(recorded)
    types = type_codes(properties_h)
    failures = []
    summary = []
    for name, witness in (("as recorded", False), ("witness", True)):
        session = build(frames, types, witness)
        if name == "as recorded" and len(argv) == 6:
            with open(argv[5], "w", encoding="utf-8") as f:
                f.write("\n".join(session.lines) + "\n")
        counts = verify(name, session, run(sim, session), failures)
        summary.append("%s: %d frames sent, %d of them answered, %d answers"
                       % (name, counts["steps"], counts["answered"], counts["answers"]))
        if witness:
            # set_id()'s id 0 on the three drives; set_mode()'s 8 on the
            # three e-stopped drives, then on drive 1
            if session.refusals != 7:
                failures.append("witness: %d writes refused by the contract, want 7" % session.refusals)
            summary.append("%d writes refused as the contract says" % session.refusals)
    for failure in failures:
        print("FAIL:", failure)
    print("%d recorded frames; %s" % (len(frames), "; ".join(summary)))
    print("the recording through daran-sim --can: %s" % ("failed" if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
