"""A drop-in for the vendor's serial library (DrEmpower_ascii.py v2.0): the
same module-level functions, arguments, defaults and return values, over
daran's link (the C client builds every line). A script written for it runs
with one changed import:

    import daran.vendor as dr        # was: import DrEmpower_ascii as dr
    dr.connect("/dev/ttyUSB0")       # was: the library's own `uart = serial.Serial(...)`
    dr.set_angle(1, 90, 10, 25, 1)

The port is also taken from $DARAN_PORT at the first call. What differs (each
listed in docs/python.md): replies are matched to their request by the C link
(no fixed 50 ms read window), a command the drive refuses returns False
instead of True, set_angles refreshes its cache of positions whenever the ids
change, and numbers go out as the drive reads them (shortest float32)."""
import os
import time

from .. import DaranError
from .._link import lookup
from ._plan import sync_duration

READ_FLAG = 0   # 1: the last read succeeded, -1: it failed (the vendor's global)
CHECK_FLAG = 0  # 1: every line with its ` *N` checksum
TRAJ_MODE = 1   # the drives' traj_mode, for set_angles' timing (set_traj_mode)
cur_angle_list = []  # set_angles' cache of the drives' targets
uart_baudrate = 115200

INPUT_MODE_PASSTHROUGH = 1
INPUT_MODE_VEL_RAMP = 2
INPUT_MODE_TORQUE_RAMP = 6
AXIS_STATE_IDLE = 1
AXIS_STATE_CLOSED_LOOP_CONTROL = 8

_link = None
_cache_ids = []


def connect(port=None, baudrate=115200, **options):
    """Use `port` (a path, or an open daran link such as daran.sim()) for every call."""
    global _link
    import daran
    if port is None:
        port = os.environ.get("DARAN_PORT")
        if port is None:
            raise RuntimeError("daran.vendor: call connect(port) or set DARAN_PORT")
    _link = port if hasattr(port, "transact") else daran.open(port, baudrate, **options)
    return _link


def _line():
    link = _link or connect()
    link.set_checksum(bool(CHECK_FLAG))
    return link


def _send(name, command, id_num, values=(), **request):
    """A command answered with nothing: True once sent, False when refused or failed."""
    try:
        _line().transact(command, int(id_num), [float(v) for v in values], **request)
    except DaranError as exc:
        print(f"---error in {name}---:", exc)
        return False
    return True


def _read(name, command, id_num, expected=0, **request):
    """A query: its values, READ_FLAG 1; None and READ_FLAG -1 when it failed."""
    global READ_FLAG
    link = _line()
    try:
        link.transact(command, int(id_num), **request)
        values = link.values(expected)
    except DaranError as exc:
        READ_FLAG = -1
        print(f"---error in {name}---:", exc)
        return None
    READ_FLAG = 1
    return values


def _vendor_path(id_num, prop):
    """The vendor's property name as a path and scope: anything naming `axis` is an
    axis property (`axis0.x`, `axis.x`), the rest system ones (the id last)."""
    if "odrv" in prop:
        prop = prop.split(".", 1)[-1]
    if "axis" in prop:
        bare = prop.split(".", 1)[-1]
        return f"axis{id_num}.{bare}", False, lookup(bare)
    return prop, True, lookup(prop)


def send_command(order="", cn=0):
    """A line of the caller's, sent once (` *N` when cn): True when the drive took it."""
    link = _link or connect()
    link.set_checksum(bool(cn))
    try:
        link.send_line(order)
    except DaranError as exc:
        print("---error in send_command---:", exc)
        return False
    finally:
        link.set_checksum(bool(CHECK_FLAG))
    return True


# -- motion ---------------------------------------------------------------------------------

def preset_angle(id_num=1, angle=0, t=0, param=0, mode=0):
    if mode in (0, 1):
        return _send("preset_angle", "MS", id_num, (angle, abs(t), abs(param)))
    if mode == 2:
        return _send("preset_angle", "MS", id_num, (angle, t, param))
    return None


def preset_speed(id_num=0, speed=10, param=0, mode=1):
    if mode == 1:
        return _send("preset_speed", "MS", id_num,
                     (speed, 0 if speed == 0 else param, INPUT_MODE_PASSTHROUGH))
    return _send("preset_speed", "MS", id_num, (speed, param, INPUT_MODE_VEL_RAMP))


def preset_torque(id_num=0, torque=0.1, param=0, mode=1):
    if mode == 1:
        return _send("preset_torque", "MS", id_num, (torque, 0, INPUT_MODE_PASSTHROUGH))
    return _send("preset_torque", "MS", id_num, (torque, param, INPUT_MODE_TORQUE_RAMP))


def set_angle(id_num=1, angle=0, speed=0, param=0, mode=0):
    if mode == 0:
        return _send("set_angle", "T", id_num, (angle, abs(speed), abs(param)))
    if mode == 1:
        if speed > 0 and param > 0:
            return _send("set_angle", "Q", id_num, (angle, abs(speed), abs(param)))
        print("speed or accel <= 0")
        return True
    if mode == 2:
        return _send("set_angle", "P", id_num, (angle, speed, param))
    return True


def _start(word, relative):
    command = {"mt": "MT", "mq": "MQ", "mp": "MP"}[word]
    return _send("set_angles", command, 0, (relative,))


def set_angles(id_list=[1, 2, 3], angle_list=[150.0, 150.0, 150.0], speed=10, param=10,  # noqa: B006
               mode=1):
    global cur_angle_list, _cache_ids
    # the vendor refreshes its cache only when the list's length changes; a cache of
    # other drives is stale as well
    if len(cur_angle_list) != len(angle_list) or list(id_list) != _cache_ids:
        cur_angle_list = []
        for id_num in id_list:
            state = get_state(id_num=id_num)
            cur_angle_list.append(state[0] if READ_FLAG == 1 else 0)
        _cache_ids = list(id_list)
    if len(id_list) != len(angle_list):
        return None
    if mode == 0:
        for id_num, angle in zip(id_list, angle_list):
            preset_angle(id_num, angle, speed, param, mode)
        _start("mt", 0)
    elif mode == 1:
        if speed > 0 and param > 0:
            delta = max(abs(a - c) for a, c in zip(angle_list, cur_angle_list))
            t, _ = sync_duration(delta, speed, param, TRAJ_MODE)
            for id_num, angle in zip(id_list, angle_list):
                preset_angle(id_num, angle, t, param, mode)
            _start("mq", 0)
        else:
            print("speed or accel <= 0")
    elif mode == 2:
        for id_num, angle in zip(id_list, angle_list):
            preset_angle(id_num, angle, speed, param, mode)
        _start("mp", 0)
    cur_angle_list = list(angle_list)
    return None


def step_angle(id_num=1, angle=0, speed=0, param=0, mode=0):
    return step_angles([id_num], [angle], speed, param, mode)


def step_angles(id_list=[1, 2, 3], angle_list=[150.0, 150.0, 150.0], speed=10, param=10,  # noqa: B006
                mode=1):
    if len(id_list) != len(angle_list):
        return None
    if mode == 0:
        for id_num, angle in zip(id_list, angle_list):
            preset_angle(id_num, angle, speed, param, mode)
        _start("mt", 1)
    elif mode == 1:
        if speed > 0 and param > 0:
            t, _ = sync_duration(max(abs(a) for a in angle_list), speed, param, TRAJ_MODE)
            for id_num, angle in zip(id_list, angle_list):
                preset_angle(id_num, angle, t, param, mode)
            _start("mq", 1)
        else:
            print("speed or accel <= 0")
    elif mode == 2:
        for id_num, angle in zip(id_list, angle_list):
            preset_angle(id_num, angle, speed, param, mode)
        _start("mp", 1)
    return None


def set_speed(id_num=0, speed=10, param=0, mode=1):
    if mode == 1:
        return _send("set_speed", "V", id_num,
                     (speed, 0 if speed == 0 else param, INPUT_MODE_PASSTHROUGH))
    return _send("set_speed", "V", id_num, (speed, param, INPUT_MODE_VEL_RAMP))


def set_speeds(id_list=[1, 2, 3], speed_list=[10.0, 20.0, 30.0], param=0, mode=1):  # noqa: B006
    if len(id_list) == len(speed_list):
        for id_num, speed in zip(id_list, speed_list):
            preset_speed(id_num, speed, param, mode)
        return _send("set_speeds", "MV", 0)
    return True


def set_torque(id_num=0, torque=0.1, param=0, mode=1):
    if mode == 1:
        return _send("set_torque", "C", id_num, (torque, 0, INPUT_MODE_PASSTHROUGH))
    return _send("set_torque", "C", id_num, (torque, param, INPUT_MODE_TORQUE_RAMP))


def set_torques(id_list=[1, 2, 3], torque_list=[3.0, 4.0, 5.0], param=0, mode=1):  # noqa: B006
    if len(id_list) == len(torque_list):
        for id_num, torque in zip(id_list, torque_list):
            preset_torque(id_num, torque, param, mode)
        return _send("set_torques", "MC", 0)
    return True


def impedance_control(id_num=0, pos=0, vel=0, tff=0, kp=0, kd=0):
    _send("impedance_control", "D", id_num, (pos, vel, tff, kp, kd))


def estop(id_num=0):
    _send("estop", "ST", id_num)


# -- settings -------------------------------------------------------------------------------

def set_id(id_num=0, new_id=1):
    write_property(id_num=id_num, property="axis0.config.can_node_id", value=new_id)
    save_config(id_num=new_id)


def set_uart_baud_rate(id_num=0, baud_rate=115200):
    write_property(id_num=id_num, property="config.uart_baudrate", value=baud_rate)
    save_config(id_num=id_num)


def set_can_baud_rate(id_num=0, baud_rate=500000):
    write_property(id_num=id_num, property="can.config.baud_rate", value=baud_rate)
    save_config(id_num=id_num)


def set_mode(id_num=0, mode=2):
    if mode == 1:
        write_property(id_num=id_num, property="axis.requested_state", value=AXIS_STATE_IDLE)
    elif mode == 2:
        write_property(id_num=id_num, property="axis.requested_state",
                       value=AXIS_STATE_CLOSED_LOOP_CONTROL)


def set_zero_position(id_num=0):
    _send("set_zero_position", "SZ", id_num)


def set_GPIO_mode(id_num=0, mode="tx_rx", param=115200):  # noqa: N802 (the vendor's name)
    enable_state = get_GPIO_mode(id_num=id_num)
    uart, step_dir = (1, 0) if mode == "tx_rx" else (0, 1)
    if mode not in ("tx_rx", "step_dir"):
        return
    if READ_FLAG == -1 or enable_state[0] != uart:
        write_property(id_num=id_num, property="config.enable_uart", value=uart)
        time.sleep(0.1)
    if READ_FLAG == -1 or enable_state[1] != step_dir:
        write_property(id_num=id_num, property="axis0.config.enable_step_dir", value=step_dir)
        time.sleep(0.1)
    write_property(id_num=id_num, property="config.uart_baudrate" if uart
                   else "axis0.output_shaft.steps_per_turn", value=param)
    time.sleep(0.1)
    get_GPIO_mode(id_num=id_num)
    save_config(id_num=id_num)
    time.sleep(0.1)
    reboot(id_num=id_num)


def set_angle_range(id_num=0, angle_min=-360, angle_max=360):
    pos_vel = get_state(id_num=id_num)
    if READ_FLAG != 1:
        print("reading the angle failed: the range was not set")
        return False
    if not angle_min <= pos_vel[0] <= angle_max:
        print(f"the output shaft is outside {[angle_min, angle_max]}: the range was not set")
        return False
    write_property(id_num=id_num, property="axis0.output_shaft.circular_setpoint_min", value=angle_min)
    write_property(id_num=id_num, property="axis0.output_shaft.circular_setpoint_max", value=angle_max)
    write_property(id_num=id_num,
                   property="axis0.config.extra_setting.enable_circular_setpoint_limit", value=1)
    save_config(id_num=id_num)
    return True


def set_traj_mode(id_num=0, mode=1):
    global TRAJ_MODE
    write_property(id_num=id_num, property="axis0.trap_traj.config.traj_mode", value=mode)
    TRAJ_MODE = mode


def write_property(id_num=0, property="", value=0):  # noqa: A002 (the vendor's argument)
    path, system, prop = _vendor_path(id_num, property)
    ok = _send("write_property", "W", id_num, path=path, system=system,
               value=value, ctype=prop.ctype if prop else None)
    return None if ok else False


# -- reading --------------------------------------------------------------------------------

def read_property(id_num=0, property=""):  # noqa: A002
    path, system, prop = _vendor_path(id_num, property)
    values = _read("read_property", "R", id_num, 1, path=path, system=system)
    if values is None:
        return None
    value = values[0]
    return prop.type(value) if prop is not None and prop.type is not float else value


def get_id(id_num=0):
    return read_property(id_num=id_num, property="axis0.config.can_node_id")


def get_state(id_num=0):
    values = _read("get_state", "F", id_num, 2)
    return None if values is None else [round(values[0], 2), round(values[1], 1)]


def get_volcur(id_num=0):
    values = _read("get_volcur", "G", id_num, 2)
    return None if values is None else [round(values[0], 1), round(values[1], 2)]


def get_GPIO_mode(id_num=0):  # noqa: N802
    enable_uart = read_property(id_num=id_num, property="config.enable_uart")
    enable_step_dir = read_property(id_num=id_num, property="axis0.config.enable_step_dir")
    if READ_FLAG == 1:
        return [enable_uart, enable_step_dir]
    return None


# -- system ---------------------------------------------------------------------------------

def clear_error(id_num=0):
    _send("clear_error", "SC", id_num)


def dump_error(id_num=0):
    global READ_FLAG
    try:
        lines = _line().transact("E", int(id_num), collect=True)
    except DaranError as exc:
        READ_FLAG = -1
        print("---error in read_error---:", exc)
        return None
    READ_FLAG = 1
    print("\n".join(line.text for line in lines))
    return None


def save_config(id_num=0):
    return None if _send("save_config", "SS", id_num) else False


def reboot(id_num=0):
    return None if _send("reboot", "SR", id_num) else False


def position_done(id_num=0):
    traj_done = 0
    while not traj_done:
        traj_done = read_property(id_num, property="axis0.controller.trajectory_done")
        if not traj_done:
            time.sleep(0.001)


def positions_done(id_list=[1, 2, 3]):  # noqa: B006
    for id_num in id_list:
        position_done(id_num)
