#!/usr/bin/python3
"""`daran-sim --usbcan` as the vendor's DrEmpower_can.py uses its USB-CAN
adapter: 16-byte packets `AA 00 <rtr> 08 00 00 <id hi> <id lo> <8 bytes>`
written to a serial port, each answer read as whatever is waiting once its
first byte has come (the library takes a read of exactly 16 bytes with byte
3 = 8 as a frame, the id in bytes 6..7). Checks: the get_id() broadcast
answered by drive 1 then 2 (two packets), a unicast read answered by one
whole packet, a trajectory frame moving drive 2 read back by fast read, a
damaged packet skipped, and nothing answered while drive 2 is mute. Exits 77
without python3-serial or ptys.

usage: pty_usbcan.py DARAN_SIM
"""
import sys
import time

from can_pty_support import FAST_READ, GET_ID, READ_POS, T_90, f32, require, run, u32

serial = require("serial", "python3-serial")


def packet(can_id, data, rtr=0):
    return bytes([0xAA, 0, rtr, 8, 0, 0, can_id >> 8, can_id & 0xFF]) + bytes(data)


def send(port, can_id, data):
    """As the library's write: what is waiting is discarded first."""
    port.reset_input_buffer()
    port.write(packet(can_id, data))


def answer(port, wait=0.5):
    """What is waiting once a first byte has come (b"" after @wait s)."""
    deadline = time.time() + wait
    while port.in_waiting == 0:
        if time.time() > deadline:
            return b""
        time.sleep(0.0005)
    got = b""
    while port.in_waiting > 0:
        got += port.read(port.in_waiting)
    return got


def as_frame(raw):
    """The library's reading of a 16-byte packet: (id, data), or None."""
    if len(raw) != 16 or raw[0] != 0xAA or raw[3] != 8:
        return None
    return raw[6] << 8 | raw[7], raw[8:16]


def checks(sim, failures):
    path = sim.paths[0]
    port = serial.Serial(path, 115200, timeout=1)

    # a broadcast: both drives answer, in one tick, back to back
    send(port, *GET_ID)
    time.sleep(0.05)
    raw = answer(port)
    if [as_frame(raw[k:k + 16]) for k in (0, 16)] != [
            (0x03E, GET_ID[1][:4] + bytes([1, 0, 0, 0])),
            (0x05E, GET_ID[1][:4] + bytes([2, 0, 0, 0]))] or len(raw) != 32:
        failures.append("get_id() answers: %r" % raw)

    # one drive: one whole packet, as the library's read wants it
    send(port, 2 << 5 | 0x1E, GET_ID[1])
    reply = as_frame(answer(port))
    if reply is None or reply[0] != 0x05E or u32(reply[1], 4) != 2:
        failures.append("unicast get_id(2): %r" % (reply,))

    # set_angle(2, 90, 0, 10, 0), then get_state(2): a status frame
    send(port, 2 << 5 | 0x19, T_90)
    time.sleep(1.5)
    send(port, 2 << 5 | 0x1E, FAST_READ)
    reply = as_frame(answer(port))
    if reply is None or reply[0] != 0x043 or abs(f32(reply[1]) - 90) > 0.5:
        failures.append("get_state(2) after the move: %r" % (reply,))

    # noise and a damaged packet (DLC 9) before a good one: only the good
    # one is taken
    port.reset_input_buffer()
    bad = bytearray(packet(1 << 5 | 0x1E, READ_POS))
    bad[3] = 9
    port.write(b"\x00\x13" + bytes(bad) + packet(1 << 5 | 0x1E, READ_POS))
    reply = as_frame(answer(port))
    if reply is None or reply[0] != 0x03E or reply[1][:2] != READ_POS[:2]:
        failures.append("the good packet after a damaged one: %r" % (reply,))
    if answer(port, 0.1):
        failures.append("the damaged packet was answered")

    # a drive that stopped answering: silence, then its answers again
    sim.directive("!fault 2 can-mute")
    time.sleep(0.05)
    send(port, 2 << 5 | 0x1E, READ_POS)
    if answer(port, 0.2):
        failures.append("a mute drive answered")
    sim.directive("!fault 2 can-recover")
    time.sleep(0.05)
    send(port, 2 << 5 | 0x1E, READ_POS)
    reply = as_frame(answer(port))
    if reply is None or reply[0] != 0x05E or abs(f32(reply[1], 4) - 90) > 0.5:
        failures.append("drive 2 after recovering: %r" % (reply,))
    port.close()


if __name__ == "__main__":
    sys.exit(run('USB-CAN packets on --usbcan', ['--drives', '2', '--usbcan'], 1, checks))
