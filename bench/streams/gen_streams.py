#!/usr/bin/env python3
"""Generate the recorded request streams the host benchmarks replay.

Run once; the output is committed, so every figure in docs/performance.md is
measured on the same bytes. A fixed seed makes a re-run reproduce the files
exactly (python3 >= 3.6, random.Random is stable across versions for the
calls used here: random(), randrange(), choice()).

    python3 bench/streams/gen_streams.py            # rewrites bench/streams/*.txt

Streams (one request per line, no timestamps; lines are what a host sends):
  reference.txt  the CTest reference: a 1 kHz `t` streaming session with
                 f/g polls, moves, ms/mq starts and r/w tuning mixed in
  tuning.txt     a gain-tuning session: r/w heavy, step moves, polls
  bus.txt        three drives on one link: ms/mq/mt starts, lines for ids 2
                 and 3 (silent here), broadcast id 0
  families/*.txt one command family per file, 1000 lines each, for the
                 per-family table (t, t_cs, q, p, v, c, d, ms_mq, r, w, f, g,
                 e, errors)
  contract.txt   not measured: the edges of the contract (zero rates, S-curve
                 mq, s32 and the integer ranges, error registers, `e`), for
                 compare_traces.py only; written without the random generator,
                 so the streams above stay byte for byte what they were
In the three sessions a third of the lines carry a (correct) checksum.
"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
SEED = 20261122

RW_F32 = [
    # (path after axisN., low, high) - writable floats and sensible values
    ("controller.config.pos_gain", 5.0, 80.0),
    ("controller.config.vel_gain", 0.01, 0.5),
    ("controller.config.vel_integrator_gain", 0.0, 2.0),
    ("controller.config.vel_limit", 1.0, 50.0),
    ("controller.config.input_filter_bandwidth", 5.0, 200.0),
    ("motor.config.current_lim", 1.0, 40.0),
    ("motor.config.torque_lim", 0.5, 20.0),
    ("motor.config.current_control_bandwidth", 500.0, 3000.0),
    ("output_shaft.vel_limit", 10.0, 600.0),
    ("output_shaft.torque_lim", 0.5, 20.0),
    ("output_shaft.vel_ramp_rate", 1.0, 500.0),
    ("output_shaft.torque_ramp_rate", 0.1, 50.0),
    ("output_shaft.load_inertia", 0.0, 0.1),
    ("output_shaft.circular_setpoint_min", -360.0, -1.0),
    ("output_shaft.circular_setpoint_max", 1.0, 360.0),
    ("fet_thermistor.config.temp_limit_lower", 60.0, 90.0),
    ("fet_thermistor.config.temp_limit_upper", 90.0, 120.0),
]
R_AXIS = [
    "controller.trajectory_done", "motor.current_control.Iq_measured",
    "output_shaft.pos_estimate", "output_shaft.vel_estimate",
    "output_shaft.torque_estimate", "output_shaft.pos_setpoint",
    "output_shaft.input_pos", "fet_thermistor.temperature",
    "motor_thermistor.temperature", "current_state", "error",
    "controller.config.pos_gain", "controller.config.vel_gain",
    "config.can_node_id", "config.watchdog_timeout",
]
R_SYSTEM = ["vbus_voltage", "ibus", "config.uart_baudrate", "can.config.baud_rate",
            "fw_version", "serial_number"]


class Gen:
    def __init__(self, seed):
        self.rnd = random.Random(seed)

    def num(self, x):
        """A float as some host would print it: Python str(), C %f, or a
        rounded short form."""
        r = self.rnd.random()
        if r < 0.25:
            return repr(float(x))            # vendor Python client: up to 17 digits
        if r < 0.55:
            return "%f" % x                  # vendor C library: printf("%f")
        text = "%.3f" % x                    # a host that rounds
        text = text.rstrip("0").rstrip(".")
        return "0" if text in ("", "-0") else text

    def small_int(self, lo, hi):
        return str(self.rnd.randrange(lo, hi + 1))


def with_checksum(line, trailing_space=True):
    """Append a correct checksum the way the vendor client does: the payload
    (trailing space included) XORed byte by byte."""
    payload = line + (" " if trailing_space else "")
    x = 0
    for ch in payload.encode("ascii"):
        x ^= ch
    return "%s*%d" % (payload, x)


def maybe_checksum(g, line, share=1.0 / 3.0):
    if g.rnd.random() < share:
        return with_checksum(line, g.rnd.random() < 0.8)
    return line


# ---- command builders -------------------------------------------------------

def t_line(g, pos, ident=1):
    r = g.rnd.random()
    if r < 0.5:
        return "t %d %s 0 25" % (ident, g.num(pos))
    if r < 0.8:
        return "t %d %s" % (ident, g.num(pos))
    return "t %d %s %s" % (ident, g.num(pos), g.num(g.rnd.uniform(-30, 30)))


def q_line(g, ident=1):
    pos = g.rnd.uniform(-180, 180)
    if g.rnd.random() < 0.7:
        return "q %d %s %s %s" % (ident, g.num(pos), g.num(g.rnd.uniform(5, 60)),
                                  g.num(g.rnd.uniform(1, 50)))
    return "q %d %s" % (ident, g.num(pos))


def p_line(g, ident=1):
    return "p %d %s %s %s" % (ident, g.num(g.rnd.uniform(-90, 90)), g.num(g.rnd.uniform(-10, 10)),
                              g.num(g.rnd.uniform(-0.5, 0.5)))


def v_line(g, ident=1):
    vel = g.rnd.uniform(-60, 60)
    if g.rnd.random() < 0.5:
        return "v %d %s %s 1" % (ident, g.num(vel), g.num(g.rnd.uniform(-0.5, 0.5)))
    return "v %d %s %s 2" % (ident, g.num(vel), g.num(g.rnd.uniform(1, 50)))


def c_line(g, ident=1):
    torque = g.rnd.uniform(-2, 2)
    r = g.rnd.random()
    if r < 0.5:
        return "c %d %s 0 1" % (ident, g.num(torque))
    return "c %d %s %s %d" % (ident, g.num(torque), g.num(g.rnd.uniform(0.01, 5)),
                              2 if r < 0.75 else 6)


def d_line(g, ident=1):
    return "d %d %s %s %s %s %s" % (ident, g.num(g.rnd.uniform(-90, 90)), g.num(g.rnd.uniform(-5, 5)),
                                    g.num(g.rnd.uniform(-0.5, 0.5)), g.num(g.rnd.uniform(0, 0.5)),
                                    g.num(g.rnd.uniform(0, 0.05)))


def ms_mq_lines(g, ident=1):
    """A timed synchronous move: preset then start (absolute or relative).
    The duration leaves room, so the move is always feasible."""
    pos = g.rnd.uniform(-90, 90)
    acc = g.rnd.uniform(5, 30)
    # a = 6*acc deg/s^2; feasible when T >= 2 sqrt(D/a). Relative starts
    # let the setpoint wander, so budget D = 4000 deg to stay feasible.
    dur = 2.0 * math.sqrt(4000.0 / (6.0 * acc)) * g.rnd.uniform(1.05, 2.0)
    return ["ms %d %s %s %s" % (ident, g.num(pos), g.num(dur), g.num(acc)),
            "mq %d %d" % (g.rnd.choice([ident, 0]), g.rnd.choice([0, 0, 1]))]


def r_line(g):
    if g.rnd.random() < 0.75:
        return "r axis1.%s" % g.rnd.choice(R_AXIS)
    return "r %s 1" % g.rnd.choice(R_SYSTEM)


def w_line(g):
    r = g.rnd.random()
    if r < 0.85:
        path, lo, hi = g.rnd.choice(RW_F32)
        return "w axis1.%s %s" % (path, g.num(g.rnd.uniform(lo, hi)))
    if r < 0.9:
        return "w config.uart_baudrate %s 1" % g.rnd.choice(["9600", "57600", "115200"])
    if r < 0.95:
        return "w axis1.requested_state 8"
    return "w axis1.config.enable_watchdog 0"


ERRORS = [
    "x 1", "tt 1 10", "t", "t 1", "t 64 10", "t 1.5 10", "t 1 abc", "t 1 10 0 -5",
    "t 1 1e39", "q 1 10 -3", "v 1 10 0 7", "v 1 10 0 2", "c 1 1 0 9", "c 1 1 -1 6",
    "d 1 1 2 3 -1 0", "d 1 1 2 3", "ms 1 1 2", "mq 1 5", "r axis1.nope",
    "r axis1.controller.config.pos_gainx", "r nothing_here 1", "w vbus_voltage 5 1",
    "w axis1.error 0", "w axis1.controller.config.pos_gain -1",
    "w config.uart_baudrate 1234 1", "w axis1.config.can_node_id 64",
    "w axis1.requested_state 3", "f 1 2", "g", "e 99", "r axis1.error 1",
    "f 1 *1234", "f 1 *", "f 1 *12x", "f 1 *86", "t 1 10 0 25 *80", "w axis1.x 5 *7",
    "q 1 nan", "p 1 inf", "v 1 0x10", "t 1 10" + " " * 130,
]


def error_line(g):
    line = g.rnd.choice(ERRORS)
    return line


# ---- sessions --------------------------------------------------------------

def reference_session(g, count):
    """1 kHz trajectory streaming with the polls and commands a real host
    interleaves."""
    out = [maybe_checksum(g, "r axis0.config.can_node_id"), maybe_checksum(g, "i 1"),
           maybe_checksum(g, "e 1"), maybe_checksum(g, "g 1"),
           maybe_checksum(g, "w axis1.controller.config.input_filter_bandwidth 25")]
    k = 0
    while len(out) < count:
        k += 1
        pos = 90.0 * math.sin(2 * math.pi * k / 2000.0) + 10.0 * math.sin(2 * math.pi * k / 170.0)
        out.append(maybe_checksum(g, t_line(g, pos)))
        if k % 10 == 0:
            out.append(maybe_checksum(g, "f 1"))
        if k % 100 == 0:
            out.append(maybe_checksum(g, "g 1"))
        if k % 500 == 0:
            out.append(maybe_checksum(g, "e 1"))
        if k % 250 == 0:
            maker = g.rnd.choice([q_line, p_line, v_line, c_line, d_line])
            out.append(maybe_checksum(g, maker(g)))
        if k % 400 == 0:
            out.extend(maybe_checksum(g, l) for l in ms_mq_lines(g))
        if k % 300 == 0:
            out.append(maybe_checksum(g, r_line(g)))
        if k % 700 == 0:
            out.append(maybe_checksum(g, w_line(g)))
        if k % 1000 == 0:
            out.append(maybe_checksum(g, "u 1"))
        if k % 997 == 0:
            out.append(error_line(g))
    return out[:count]


def tuning_session(g, count):
    out = []
    while len(out) < count:
        out.append(maybe_checksum(g, w_line(g)))
        for _ in range(g.rnd.randrange(1, 4)):
            out.append(maybe_checksum(g, q_line(g)))
            for _ in range(g.rnd.randrange(2, 6)):
                out.append(maybe_checksum(g, "f 1"))
                out.append(maybe_checksum(g, r_line(g)))
        out.append(maybe_checksum(g, "g 1"))
        if g.rnd.random() < 0.2:
            out.append(maybe_checksum(g, g.rnd.choice([p_line, v_line, c_line, d_line])(g)))
        if g.rnd.random() < 0.05:
            out.append(maybe_checksum(g, "ss 1"))
        if g.rnd.random() < 0.02:
            out.append(error_line(g))
    return out[:count]


def bus_session(g, count):
    out = []
    while len(out) < count:
        kind = g.rnd.random()
        if kind < 0.4:
            for ident in (1, 2, 3):
                out.extend(maybe_checksum(g, l) for l in ms_mq_lines(g, ident)[:1])
            out.append(maybe_checksum(g, "mq 0 0"))
        elif kind < 0.55:
            for ident in (1, 2, 3):
                out.append(maybe_checksum(g, "ms %d %s 0 %s" % (ident, g.num(g.rnd.uniform(-90, 90)),
                                                                g.num(g.rnd.uniform(5, 100)))))
            out.append(maybe_checksum(g, "mt 0 0"))
        else:
            ident = g.rnd.choice([1, 1, 2, 3])
            out.append(maybe_checksum(g, t_line(g, g.rnd.uniform(-90, 90), ident)))
        for ident in (1, 2, 3):
            if g.rnd.random() < 0.5:
                out.append(maybe_checksum(g, "f %d" % ident))
    return out[:count]


def family(g, name, count=1000):
    out = []
    while len(out) < count:
        if name == "t":
            out.append(t_line(g, g.rnd.uniform(-180, 180)))
        elif name == "t_cs":
            out.append(with_checksum(t_line(g, g.rnd.uniform(-180, 180)), g.rnd.random() < 0.8))
        elif name == "q":
            out.append(q_line(g))
        elif name == "p":
            out.append(p_line(g))
        elif name == "v":
            out.append(v_line(g))
        elif name == "c":
            out.append(c_line(g))
        elif name == "d":
            out.append(d_line(g))
        elif name == "ms_mq":
            out.extend(ms_mq_lines(g))
        elif name == "r":
            out.append(r_line(g))
        elif name == "w":
            out.append(w_line(g))
        elif name in ("f", "g", "e"):
            out.append("%s 1%s" % (name, " " if g.rnd.random() < 0.5 else ""))
        elif name == "errors":
            out.append(error_line(g))
        else:
            raise ValueError(name)
    return out[:count]


def contract_lines():
    """Every line here is checked by compare_traces.py: both parsers must
    make the same HAL calls and answer the same errors (protocol.md section
    10). The bench HAL moves the setpoint to each move's target."""
    lines = [
        # zero rates (10.1)
        "t 1 10 0 0", "t 1 11 0 -0", "t 1 12 0 -1", "t 1 13 5 25",
        "q 1 20 30 0", "q 1 21 30 -0", "q 1 22 0 5", "q 1 23 -1 5", "q 1 24 30 -2", "q 1 25 30",
        "v 1 10 0 2", "v 1 10 -0 2", "v 1 10 -1 2", "v 1 10 0 1", "v 1 10 2.5 2",
        "c 1 1 0 6", "c 1 1 0 2", "c 1 1 -0.5 6", "c 1 1 -0.5 1",
        "ms 1 30 5 0", "mt 1 0", "ms 1 31 5 -1", "mt 1 0", "ms 1 40 5 12", "mt 1 1",
        "ms 1 30 5 10", "mt 1 0",
        "ms 1 30 0 10", "mq 1 0", "ms 1 30 0 0", "mq 1 0", "ms 1 0 0 10", "mq 1 1",
        "ms 1 30 0 10", "mq 1 1", "ms 1 45 2 0", "mq 1 0", "ms 1 45 -1 10", "mq 1 0",
        "ms 1 45 2 -1", "mq 1 0", "ms 1 120 2 10", "mq 1 0", "ms 1 -100 1.5 40", "mq 0 0",
        "t 1 0", "ms 1 9 0.7745966692414834 10", "mq 1 0", "ms 1 19 0.1 10", "mq 1 0",
        "ms 1 10 0 0 2", "ms 1 10 0 2", "mv 1", "ms 1 10 -0 2", "mv 1", "ms 1 10 -3 2", "mv 1",
        "ms 1 2 0 6", "mc 1", "ms 1 2 0 2", "mc 1", "ms 1 2 -1 6", "mc 1", "ms 1 2 1 7", "mc 1",
        # S-curve timing (10.3)
        "w axis1.trap_traj.config.traj_mode 2", "r axis1.trap_traj.config.traj_mode",
        "t 1 0", "ms 1 90 3 20", "mq 1 0", "ms 1 100 0.8164965809277261 20", "mq 1 0",
        "ms 1 110 0.5 20", "mq 1 0", "ms 1 10 0 20", "mq 1 1", "ms 1 -10 2 20", "mq 1 1",
        "q 1 50 10 5",
        "w axis1.trap_traj.config.traj_mode 1", "w axis1.trap_traj.config.traj_mode 3",
        "w axis1.trap_traj.config.traj_mode 0",
        # s32 (10.2)
        "w axis1.motor.config.direction -1", "r axis1.motor.config.direction",
        "w axis1.motor.config.direction 1", "w axis1.motor.config.direction 0",
        "w axis1.motor.config.direction -1.0", "w axis1.motor.config.direction -2",
        "w axis1.motor.config.direction --1", "w axis1.motor.config.direction -",
        "w axis1.motor.config.direction +1", "w axis1.motor.config.direction -1.5",
        "w axis1.motor.config.pole_pairs 7", "w axis1.motor.config.pole_pairs 0",
        "w axis1.motor.config.pole_pairs 129", "w axis1.motor.config.pole_pairs 128",
        "w axis1.motor.config.pole_pairs 1e2", "r axis1.motor.config.pole_pairs",
        "w axis1.encoder.config.cpr 16384", "w axis1.encoder.config.cpr -5",
        "w axis1.encoder.config.cpr 0", "w axis1.encoder.config.cpr 2147483647",
        "w axis1.encoder.config.cpr 2147483648",
        "w axis1.config.extra_setting.stored_turns_counts -2147483648",
        "r axis1.config.extra_setting.stored_turns_counts",
        "w axis1.config.extra_setting.stored_turns_counts -2147483649",
        "w axis1.config.extra_setting.stored_turns_counts 2147483647",
        "w axis1.config.extra_setting.stored_turns_counts -0",
        "r axis1.encoder.turn_abs", "r axis1.encoder.pos_abs", "w axis1.encoder.pos_abs 5",
        # integer ranges
        "w axis1.controller.config.control_mode 3", "w axis1.controller.config.control_mode 4",
        "w axis1.controller.config.control_mode 0", "w axis1.controller.config.input_mode 5",
        "w axis1.controller.config.input_mode 4", "w axis1.controller.config.input_mode 9",
        "w axis1.motor.config.motor_type 2", "w axis1.motor.config.motor_type 1",
        "w can.config.protocol 1 1", "w can.config.protocol 2 1",
        "w can.config.heartbeat_ms 4294967295 1", "w can.config.heartbeat_ms 4294967296 1",
        "w can.config.heartbeat_ms -1 1", "w can.config.heartbeat_ms -0 1",
        "w config.dc_max_negative_current -10 1", "w config.dc_max_negative_current 5 1",
        "w config.dc_max_negative_current -0 1", "w axis1.config.enable_watchdog 2",
        "w config.enable_uart 1 1", "w axis1.config.enable_step_dir 1",
        "w axis1.output_shaft.vel_ramp_rate 0", "w axis1.output_shaft.vel_ramp_rate -1",
        "w axis1.controller.config.input_filter_bandwidth 0",
        "w axis1.output_shaft.trap_traj_accel_limit 0", "w axis1.output_shaft.trap_traj_vel_limit 0",
        "r serial_number_l 1", "r serial_number_h 1", "w serial_number_l 5 1",
        # error registers (10.4): writable with 0 only
        "w axis1.error 0", "w axis1.error 1", "w axis1.motor.error 0", "w axis1.controller.error 5",
        "w axis1.encoder.error 0", "w axis1.fet_thermistor.error 0",
        "w axis1.motor_thermistor.error 0.0", "w can.error 0 1", "w can.error 1 1",
        "w axis1.config_warnings 0", "r axis1.config_warnings", "r axis1.motor.error",
        "e 1", "st 1", "e 1", "t 1 10", "w axis1.requested_state 8", "sc 1", "e 1", "t 1 10",
        "w axis1.requested_state 8", "t 1 10", "e 0", "e 2",
    ]
    return lines + [with_checksum(l) for l in lines]


FAMILIES = ["t", "t_cs", "q", "p", "v", "c", "d", "ms_mq", "r", "w", "f", "g", "e", "errors"]


def write(path, lines):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="ascii", newline="\n") as f:
        for line in lines:
            f.write(line + "\n")
    size = os.path.getsize(path)
    assert size < 400 * 1024, (path, size)
    print("%-40s %6d lines %7d bytes" % (os.path.relpath(path, HERE), len(lines), size))


def main():
    g = Gen(SEED)
    write(os.path.join(HERE, "reference.txt"), reference_session(g, 12000))
    write(os.path.join(HERE, "tuning.txt"), tuning_session(g, 10000))
    write(os.path.join(HERE, "bus.txt"), bus_session(g, 10000))
    for name in FAMILIES:
        write(os.path.join(HERE, "families", name + ".txt"), family(g, name))
    write(os.path.join(HERE, "contract.txt"), contract_lines())


if __name__ == "__main__":
    main()
