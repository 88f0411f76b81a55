#!/usr/bin/python3
"""`daran-sim --pty --slcan --usbcan`: three pseudo-terminals, their paths
on stdout in that order, each answering its own protocol (an ASCII line, an
slcan command, a USB-CAN packet), and the two adapters being two nodes of
one bus: a frame the slcan host sends reaches the USB-CAN host (and the
drives), never its own sender. Exits 77 without python3-serial or ptys.

usage: pty_can_links.py DARAN_SIM
"""
import sys
import time

from can_pty_support import GET_ID, require, run

serial = require("serial", "python3-serial")


def read_until(port, end, wait=1.0):
    got = b""
    deadline = time.time() + wait
    while not got.endswith(end) and time.time() < deadline:
        got += port.read(1)
    return got


def checks(sim, failures):
    if len(set(sim.paths)) != 3:
        failures.append("three different pty paths: %r" % sim.paths)
        return
    ascii_port, slcan_port, usbcan_port = (serial.Serial(p, 115200, timeout=1) for p in sim.paths)
    ascii_port.write(b"r axis2.config.can_node_id \n")
    if read_until(ascii_port, b"\n") != b"2\r\n":
        failures.append("the first path is not the ASCII link")
    slcan_port.write(b"V\rO\r")
    if read_until(slcan_port, b"\r") + read_until(slcan_port, b"\r") != b"V0100\r\r":
        failures.append("the second path is not the slcan adapter")
    # the slcan host's get_id() broadcast: the USB-CAN host sees it, then
    # the two answers; the slcan host sees the two answers only
    usbcan_port.reset_input_buffer()
    slcan_port.write(b"t01E8" + GET_ID[1].hex().upper().encode() + b"\r")
    time.sleep(0.1)
    seen = usbcan_port.read(usbcan_port.in_waiting)
    ids = [seen[k + 6] << 8 | seen[k + 7] for k in range(0, len(seen), 16)]
    if ids != [0x01E, 0x03E, 0x05E]:
        failures.append("the USB-CAN host saw %r" % seen.hex())
    lines = slcan_port.read(slcan_port.in_waiting).split(b"\r")
    if lines != [b"z", b"t03E81979030001000000", b"t05E81979030002000000", b""]:
        failures.append("the slcan host saw %r" % lines)
    for port in (ascii_port, slcan_port, usbcan_port):
        port.close()


if __name__ == "__main__":
    sys.exit(run('--pty, --slcan and --usbcan together', ['--drives', '2', '--pty', '--slcan', '--usbcan'], 3, checks))
