#!/usr/bin/python3
"""`daran-sim --drives 3 --pty --bridge` as a host sees one gateway: pyserial
on the one pseudo-terminal, lines for drives 2 and 3 answered through drive
1's bridge over the CAN bus in real time. Checked: queries for ids 2 and 3
answered with their values; lines written at once answered in their
order, more of them than drive 1's receive ring holds (the next line waits
while a query does); a motion for drive 3 moving it alone;
`error: no reply` for an absent id and for a muted drive,
after the bridge's 10 ms; a bridged query from stdin answered on stdout,
not on the pty; the console's log of the bridged frames. Exits 77
(skipped) without python3-serial or without ptys.

usage: pty_bridge.py DARAN_SIM
"""
import sys
import time

from can_pty_support import require, run

serial = require("serial", "python3-serial")


def checks(sim, failures):
    port = serial.Serial(sim.paths[0], 115200, timeout=2)

    def answers(lines, count=None):
        """The reply lines to @lines, written at once."""
        port.write("".join(line + "\n" for line in lines).encode("ascii"))
        got = [port.readline().decode("ascii") for _ in range(count or len(lines))]
        return [reply.rstrip("\r\n") for reply in got]

    def expect(lines, want, what):
        got = answers(lines, len(want))
        if got != want:
            failures.append("%s: %r, want %r" % (what, got, want))

    expect(["f 2"], ["0 0"], "f 2")
    # four lines at once: drive 1's answer waits behind the two bridged ones
    expect(["r serial_number 3", "i 2", "r vbus_voltage 1", "f 3"],
           ["2026000003", "100 3 2026000002", "24", "0 0"], "lines written at once")
    # more at once than drive 1's receive ring holds (128 bytes): none lost
    expect(["r axis%d.config.can_node_id" % (2 + k % 2) for k in range(12)],
           [str(2 + k % 2) for k in range(12)], "12 queries written at once")

    port.write(b"t 3 45 0 20\n")
    time.sleep(1.5)
    got = answers(["f 3", "f 2", "f 1"])
    moved = [float(reply.split()[0]) if reply[:1] in "-0123456789" else None for reply in got]
    if moved[0] is None or abs(moved[0] - 45.0) > 0.5 or moved[1] != 0.0 or moved[2] != 0.0:
        failures.append("after t 3 45: %r" % got)

    started = time.monotonic()
    expect(["f 9"], ["error: no reply"], "f 9")
    if time.monotonic() - started < 0.009:
        failures.append("f 9 answered before the bridge's 10 ms")

    sim.directive("!fault 2 can-mute")
    time.sleep(0.05)
    expect(["f 2", "r axis1.config.can_node_id"], ["error: no reply", "1"], "drive 2 muted")
    sim.directive("!fault 2 can-recover")
    time.sleep(0.05)

    # a line from stdin: its bridged answer goes to stdout, the pty gets none
    before = len(sim.console)
    sim.directive("r axis3.config.can_node_id")
    time.sleep(0.2)
    if "3\r" not in sim.console[before:]:
        failures.append("stdin's bridged query: stdout has %r" % sim.console[before:])
    port.timeout = 0.2
    stray = port.read(64)
    if stray:
        failures.append("the pty got the answer to stdin's line: %r" % stray)
    port.close()

    # the console's node saw the bridge's reads for drives 2 and 3 and the
    # t frame (id 0x079)
    log = [line.split()[2] for line in sim.console if line.startswith("can ")]
    for ident in ("05E", "07E", "079", "13E"):
        if ident not in log:
            failures.append("the console's log has no frame %s" % ident)


if __name__ == "__main__":
    sys.exit(run("pyserial on --pty --bridge", ["--drives", "3", "--pty", "--bridge"], 1, checks))
