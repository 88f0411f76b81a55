#!/usr/bin/python3
"""python-can's `slcan` interface against `daran-sim --slcan`, as a host
with a serial-line CAN adapter would use the bus: the version and serial
number, the vendor's get_id() broadcast answered by each drive with its own
id (lowest id first), a trajectory frame moving drive 2 and its position
read back by property and by fast read, the console's log of the same
frames, and, with the bus off (a directive on stdin), the adapter refusing a
frame with BEL and flagging a bus error. Exits 77 (skipped) without
python3-can (tools/install-deps installs it) or without ptys.

usage: pty_slcan.py DARAN_SIM
"""
import sys
import time

from can_pty_support import FAST_READ, GET_ID, READ_POS, T_90, f32, require, run, u32

can = require("can", "python3-can")
serial = require("serial", "python3-serial")


def frames(bus, count, timeout=1.0):
    """Up to @count frames, each within @timeout."""
    got = []
    while len(got) < count:
        msg = bus.recv(timeout)
        if msg is None:
            break
        got.append(msg)
    return got


def checks(sim, failures):
    path = sim.paths[0]
    bus = can.interface.Bus(interface="slcan", channel=path, bitrate=1000000,
                            sleep_after_open=0.1)
    if bus.get_version(1.0) != (1, 0) or bus.get_serial_number(1.0) != "SIM1":
        failures.append("adapter identity")

    bus.send(can.Message(arbitration_id=GET_ID[0], is_extended_id=False, data=GET_ID[1]))
    answers = frames(bus, 3)
    ids = [(m.arbitration_id, u32(m.data, 4)) for m in answers]
    if ids != [(0x03E, 1), (0x05E, 2), (0x07E, 3)]:
        failures.append("get_id() answers: %r" % ids)
    if frames(bus, 1, 0.1):
        failures.append("a fourth answer to get_id()")

    bus.send(can.Message(arbitration_id=2 << 5 | 0x19, is_extended_id=False, data=T_90))
    time.sleep(1.5)
    bus.send(can.Message(arbitration_id=2 << 5 | 0x1E, is_extended_id=False, data=READ_POS))
    reply = frames(bus, 1)
    if not reply or reply[0].arbitration_id != 0x05E or abs(f32(reply[0].data, 4) - 90) > 0.5:
        failures.append("pos_estimate of drive 2 after the t frame: %r" % reply)
    bus.send(can.Message(arbitration_id=2 << 5 | 0x1E, is_extended_id=False, data=FAST_READ))
    reply = frames(bus, 1)
    # a status frame of node 2 at rest: code 0 0 E T 1 = 0x03
    if not reply or reply[0].arbitration_id != 0x043 or abs(f32(reply[0].data) - 90) > 0.5:
        failures.append("fast read of drive 2: %r" % reply)
    bus.send(can.Message(arbitration_id=1 << 5 | 0x1E, is_extended_id=False, data=READ_POS))
    reply = frames(bus, 1)
    if not reply or abs(f32(reply[0].data, 4)) > 0.01:
        failures.append("drive 1 moved: %r" % reply)
    bus.shutdown()

    # the console's node saw the host's frames and the drives' answers
    time.sleep(0.1)
    log = [line.split()[2:] for line in sim.console if line.startswith("can ")]
    if ["01E", "[8]", "19", "79", "03", "00", "00", "00", "00", "00"] not in log or \
            ["07E", "[8]", "19", "79", "03", "00", "03", "00", "00", "00"] not in log:
        failures.append("console log: %r" % sim.console[:8])

    # the whole bus off: a frame is refused with BEL, F shows a bus error
    sim.directive("!fault 0 can-bus-off")
    time.sleep(0.1)
    port = serial.Serial(path, 115200, timeout=1)
    port.reset_input_buffer()
    port.write(b"O\r")
    port.write(b"t0010\r")
    port.write(b"F\r")
    answer = port.read(7)
    if answer != b"\r\aF80\r":
        failures.append("with the bus off: %r" % answer)
    sim.directive("!fault 0 can-recover")
    time.sleep(0.1)
    port.write(b"t0010\r")
    if port.read(2) != b"z\r":
        failures.append("no z after the bus recovered")
    port.close()
    time.sleep(0.1)
    if not any("refused (bus-off)" in e for e in sim.errors):
        failures.append("stderr did not report the refused frame: %r" % sim.errors)


if __name__ == "__main__":
    sys.exit(run('python-can slcan on --slcan', ['--drives', '3', '--slcan'], 1, checks))
