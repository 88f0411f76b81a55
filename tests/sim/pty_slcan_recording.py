#!/usr/bin/python3
"""The vendor's python-can frames through python-can's `slcan` interface on
`daran-sim --drives 3 --slcan`: the worked examples of the contract's 6.6
(the drive on the receiving side), each sent as recorded (the recording's
call named) or, for the ones the python library does not send, as 6.6
writes them, and each answered as 6.6 says:

  get_id() broadcast            drives 1, 2, 3 answer 0x03E 0x05E 0x07E with their ids
  get_state(3), read_property(3, 0)   a status frame of node 3 (type code ignored)
  send_command() (DLC 0)        nothing (C21); set_id() (id 0): nothing, ids kept (C14)
  write_property(2, enable_reply_state, 1) + set_speeds()
                                drive 2 answers its preset; each drive then runs
                                its velocity in feed-forward mode (raw 100 = mode 1)
  impedance_control(1, 30, 5, 0.5, 0.2, 0.05)
                                drive 1 settles where kp (30 - pos) + tff + kd (5 - vel)
                                is 0: 33.75 deg; drives 2 and 3 (no preset) go on
  preset_torque(1, -1.2, 0.2, 6) + a 0x14 start
                                drive 1 runs a torque ramp towards -1.2 Nm: it turns
                                backwards
  0x03F e2 79 01 00 01 00 xx xx (STM32: a bool as u16, bytes 6..7 left over)
                                accepted: enable_circular_setpoint_limit reads 1 (C6)
  0x048 06 .. with DLC 7        ignored: drive 2 is not e-stopped (C21)
  status frame 0x023 from the host   drive 1's can.error bit 0 (C22)
  enable_reply_state 1 on drive 1 + set_angle(1, 90, 0, 10, 0)
                                answered at once by a status frame of node 1

Exits 77 (skipped) without python3-can or without ptys.

usage: pty_slcan_recording.py DARAN_SIM RECORDING
  (RECORDING: tests/unit/can_recording_data.h or the recording's .txt)
"""
import struct
import sys
import time

from can_pty_support import f32, require, run, u32
from replay_can_recording import recording

can = require("can", "python3-can")

CAN_ERROR = 20001
CAN_NODE_ID = 31001
CIRCULAR_LIMIT = 31202


def recorded_calls(path):
    """{call: [(id, data of its DLC)]} of the recording, the first time each
    call was made."""
    calls = {}
    last = None
    for call, _pass, ident, dlc, data in recording(path):
        if call != last and call in calls:
            last = None
            continue  # a later pass's call of the same text
        calls.setdefault(call, []).append((ident, bytes(data[:dlc])))
        last = call
    return calls


def status(frame):
    """(node, E, position, velocity, torque) of a status frame, else None."""
    code = frame.arbitration_id & 0x1F
    if not code & 1 or code >= 0x08 or frame.dlc != 8:
        return None
    velocity, torque = struct.unpack_from("<hh", bytes(frame.data), 4)
    return (frame.arbitration_id >> 5, bool(code & 0x04), f32(frame.data),
            velocity / 100.0, torque / 100.0)


def checks(sim, failures):
    calls = recorded_calls(sys.argv[2])
    bus = can.interface.Bus(interface="slcan", channel=sim.paths[0], bitrate=1000000,
                            sleep_after_open=0.1)

    def send(frames):
        for ident, data in frames:
            bus.send(can.Message(arbitration_id=ident, is_extended_id=False, data=data,
                                 dlc=len(data)))

    def answers(frames, wait=0.1):
        """What the drives send within @wait of the last of @frames."""
        while bus.recv(0) is not None:
            pass
        send(frames)
        got = []
        deadline = time.monotonic() + wait
        while True:
            msg = bus.recv(max(0.0, deadline - time.monotonic()))
            if msg is None:
                return got
            got.append(msg)

    def read(node, address):
        reply = answers([(node << 5 | 0x1E, struct.pack("<HHI", address, 0, 0))])
        if len(reply) != 1 or reply[0].arbitration_id != (node << 5 | 0x1E):
            failures.append("read %d from node %d: %r" % (address, node, reply))
            return None
        return u32(reply[0].data, 4)

    def fast_read(node):
        reply = [status(m) for m in answers([(node << 5 | 0x1E, bytes(8))])]
        if len(reply) != 1 or reply[0] is None or reply[0][0] != node:
            failures.append("fast read of node %d: %r" % (node, reply))
            return (node, False, 0.0, 0.0, 0.0)
        return reply[0]

    def ids_answer(what):
        got = [(m.arbitration_id, u32(m.data, 0) & 0xFFFF, u32(m.data, 4))
               for m in answers(calls["dr.get_id()"])]
        if got != [(0x03E, CAN_NODE_ID, 1), (0x05E, CAN_NODE_ID, 2), (0x07E, CAN_NODE_ID, 3)]:
            failures.append("get_id() %s: %r" % (what, got))

    ids_answer("first")
    for call in ("dr.get_state(id_num=3)", "dr.read_property(id_num=3, property=0)"):
        got = [status(m) for m in answers(calls[call])]
        if len(got) != 1 or got[0] is None or got[0][0] != 3:
            failures.append("%s: %r" % (call, got))
    for call in ("dr.send_command()", "dr.set_id()"):
        got = answers(calls[call])
        if got:
            failures.append("%s answered: %r" % (call, got))
    ids_answer("after set_id()")

    write = "dr.write_property(id_num=2, property='axis0.config.extra_setting.enable_reply_state', value=1)"
    if answers(calls[write]):
        failures.append("a write was answered")
    got = [status(m) for m in answers(calls["dr.set_speeds()"])]
    if [s[0] if s else None for s in got] != [2]:
        failures.append("set_speeds(): want drive 2's status frame alone, got %r" % got)
    time.sleep(1.0)
    for node, want in ((1, 10.0), (2, 20.0), (3, 30.0)):
        velocity = fast_read(node)[3]
        if abs(velocity - want) > 0.5:
            failures.append("set_speeds(): drive %d at %r r/min, want %r" % (node, velocity, want))

    if answers(calls["dr.impedance_control(id_num=1, pos=30, vel=5, tff=0.5, kp=0.2, kd=0.05)"]):
        failures.append("impedance_control() was answered")
    time.sleep(3.0)
    position = fast_read(1)[2]
    if abs(position - 33.75) > 0.3:
        failures.append("impedance_control(): drive 1 settled at %r deg, want 33.75" % position)
    if abs(fast_read(2)[3] - 20.0) > 0.5:
        failures.append("the impedance start (node 0) changed drive 2, which held no preset")

    start = calls["dr.set_torques()"][-1]  # 0x008 sub-code 0x14
    answers(calls["dr.preset_torque(id_num=1, torque=-1.2, param=0.2, mode=6)"] + [start])
    time.sleep(1.0)
    if fast_read(1)[3] >= 0.0:
        failures.append("preset_torque(1, -1.2, 0.2, 6) + start: drive 1 does not turn backwards")

    # 6.6's frames that the python library does not send
    if answers([(0x03F, bytes.fromhex("e2 79 01 00 01 00 aa 55"))]):
        failures.append("the STM32 write was answered")
    if read(1, CIRCULAR_LIMIT) != 1:
        failures.append("the STM32 write (a bool as u16) was not taken")
    answers([(0x048, bytes.fromhex("06 00 00 00 00 00 00"))])
    node, estopped, _pos, velocity, _torque = fast_read(2)
    if estopped or abs(velocity - 20.0) > 0.5:
        failures.append("a 7-byte e-stop stopped drive 2")
    answers([(0x023, bytes(8))])
    if read(1, CAN_ERROR) != 1:
        failures.append("a status frame with id 1 from elsewhere: can.error is not 1")

    answers([(0x03F, bytes.fromhex("ee 79 03 00 01 00 00 00"))])
    got = [status(m) for m in answers(calls["dr.set_angle(id_num=1, angle=90, speed=0, param=10, mode=0)"])]
    if [s[0] if s else None for s in got] != [1]:
        failures.append("set_angle(1, 90) with enable_reply_state 1: %r" % got)
    bus.shutdown()


if __name__ == "__main__":
    sys.exit(run("python-can slcan: the recording's 6.6 frames on --slcan",
                 ["--drives", "3", "--slcan"], 1, checks))
