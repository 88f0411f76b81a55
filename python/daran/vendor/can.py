"""A drop-in for the vendor's python-can library (DrEmpower_socketcan.py): the
class DrEmpower with the same methods, arguments, defaults and return values,
over daran's CAN link (the frames laid out by the core's CAN codec). A script
written for it runs with one changed import:

    from daran.vendor.can import DrEmpower     # was: from DrEmpower_socketcan import DrEmpower
    dr = DrEmpower("can0", 0, 3)               # or DrEmpower(bus=any_python_can_bus)

Differences (docs/python.md): it configures no interface (no `sudo ip link`,
no slcand: give it a channel that is up, or a bus); a reply is the frame of
the node, code and address asked for, not whatever frame comes next within
1.5 ms; values are rounded to the frame's 0.01 steps, not truncated;
motor_state is a list of lists (no numpy); set_angles refreshes its cache
whenever the ids change."""
from .. import DaranError
from .._client import lib
from .._link import lookup
from .._table import PROPERTIES
from ..can import STARTS, SYSTEM, TYPE_CODES, CanLink, decode
from ._plan import sync_duration

INPUT_MODE_PASSTHROUGH = 1
INPUT_MODE_VEL_RAMP = 2
INPUT_MODE_TORQUE_RAMP = 6
AXIS_STATE_IDLE = 1
AXIS_STATE_CLOSED_LOOP_CONTROL = 8
#: dump_error's registers, in the vendor's order (can before the thermistors)
_ERROR_PATHS = ("axis0.error", "axis0.motor.error", "axis0.encoder.error",
                "axis0.controller.error", "can.error", "axis0.fet_thermistor.error",
                "axis0.motor_thermistor.error")
_FILTER_MAX = 300  # the vendor clamps an input-filter bandwidth above this


def _vendor_property(name):
    """A vendor property name (`axis0.x`, `vbus_voltage`) or CAN address -> our Property,
    None if unknown."""
    if isinstance(name, int):
        return next((p for p in PROPERTIES.values() if p.can == name and name), None)
    if not isinstance(name, str):
        return None
    if name.startswith("odrv"):
        name = name.split(".", 1)[-1]
    return lookup(name) if name.startswith("axis") else PROPERTIES.get(name)


class DrEmpower:
    READ_FLAG = 0
    TRAJ_MODE = 1

    def __init__(self, can_channel="can0", enable_reply_state=0, motor_num=1, *, bus=None,
                 link=None, **link_options):
        if link is None:
            if bus is None:
                import can
                bus = can.Bus(interface="socketcan", channel=can_channel)
            link = CanLink(bus, **link_options)
        self.link = link
        self.bus = link.bus
        self.MOTOR_NUM = motor_num
        self.enable_replay_state = enable_reply_state  # (sic) the vendor's attribute
        self.motor_state = [[0.0] * 5 for _ in range(motor_num)]
        self.cur_angle_list = []
        self._cache_ids = []
        self.reply_state_error = 0

    # -- frames ---------------------------------------------------------------------------

    def _frame(self, name, node, code, layout, values, subcode=None):
        data = self.link.frame_data()
        try:
            self.link.encode(layout, [float(v) for v in values], data)
            if subcode is not None:
                lib.daran_can_put_u32(data, subcode)
            self.link.send_frame(node, code, data)
        except DaranError as exc:
            print(f"---error in {name}---:", exc)
            return False
        return True

    def _system(self, name, node, subcode, data1=0):
        data = self.link.frame_data()
        lib.daran_can_put_u32(data, subcode)
        lib.daran_can_put_u16(data + 4, data1)
        try:
            self.link.send_frame(node, lib.DARAN_CAN_SYSTEM, data)
        except DaranError as exc:
            print(f"---error in {name}---:", exc)
            return False
        return True

    def send_command(self, id_num=0, cmd=0x09, data=[], rtr=0):  # noqa: B006
        import can
        self.bus.send(can.Message(arbitration_id=(id_num << 5) + cmd, data=bytes(data),
                                  is_extended_id=False, is_remote_frame=bool(rtr)))

    def reply_state(self, id_num=1):
        """With enable_reply_state, the status frame a motion frame makes (matched by node)."""
        if self.enable_replay_state and id_num <= self.MOTOR_NUM:
            try:
                state = self.link.status(id_num, read=False)
            except DaranError:
                self.READ_FLAG = -1
                self.reply_state_error += 1
                return True
            self._keep_state(id_num, state)
        return True

    def _keep_state(self, id_num, state):
        self.READ_FLAG = 1
        if 1 <= id_num <= self.MOTOR_NUM:
            self.motor_state[id_num - 1] = [state.position, state.velocity, state.torque,
                                            int(state.done), int(state.error)]

    # -- motion ---------------------------------------------------------------------------

    def preset_angle(self, id_num=1, angle=0, t=0, param=0, mode=0):
        if mode == 0:
            param = self._clamp_filter(param)
            values = (angle, abs(t), abs(param))
        elif mode == 1:
            values = (angle, abs(t), abs(param))
        elif mode == 2:
            values = (angle, t, param)
        else:
            return None
        self._frame("preset_angle", id_num, lib.DARAN_CAN_PRESET, lib.DARAN_CAN_LAYOUT_PRESET,
                    values)
        self.reply_state(id_num)
        return None

    def preset_speed(self, id_num=0, speed=10, param=0, mode=1):
        values = ((speed, 0 if speed == 0 else param, INPUT_MODE_PASSTHROUGH) if mode == 1
                  else (speed, param, INPUT_MODE_VEL_RAMP))
        ok = self._frame("preset_speed", id_num, lib.DARAN_CAN_PRESET,
                         lib.DARAN_CAN_LAYOUT_PRESET, values)
        self.reply_state(id_num)
        return ok

    def preset_torque(self, id_num=0, torque=0.1, param=0, mode=1):
        values = ((torque, 0, INPUT_MODE_PASSTHROUGH) if mode == 1
                  else (torque, param, INPUT_MODE_TORQUE_RAMP))
        ok = self._frame("preset_torque", id_num, lib.DARAN_CAN_PRESET,
                         lib.DARAN_CAN_LAYOUT_PRESET, values)
        self.reply_state(id_num)
        return ok

    @staticmethod
    def _clamp_filter(param):
        if param > _FILTER_MAX:
            print(f"input_filter_width = {param}, which is too big and resized to {_FILTER_MAX}")
            return _FILTER_MAX
        return param

    def set_angle(self, id_num=0, angle=0, speed=0, param=0, mode=0):
        ok = True
        if mode == 0:
            ok = self._frame("set_angle", id_num, lib.DARAN_CAN_TRACK, lib.DARAN_CAN_LAYOUT_TRACK,
                             (angle, abs(speed), abs(self._clamp_filter(param))))
        elif mode == 1:
            if speed > 0 and param > 0:
                ok = self._frame("set_angle", id_num, lib.DARAN_CAN_TRACK + 1,
                                 lib.DARAN_CAN_LAYOUT_TRAPEZOID, (angle, abs(speed), abs(param)))
            else:
                print("speed or accel <= 0")
        elif mode == 2:
            ok = self._frame("set_angle", id_num, lib.DARAN_CAN_TRACK + 2,
                             lib.DARAN_CAN_LAYOUT_PASSTHROUGH, (angle, speed, param))
        self.reply_state(id_num)
        return ok

    def _presets_then_start(self, id_list, angle_list, t, param, mode, relative, planned=False):
        if planned:
            # the vendor truncates a planned duration to the frame's 0.01 s steps (drives
            # take the shortfall, can.md C13); other values are rounded by the codec
            t = int(abs(t) / 0.01) / 100
        for id_num, angle in zip(id_list, angle_list):
            self.preset_angle(id_num, angle, t, param, mode)
        self._system("set_angles", 0, lib.DARAN_CAN_SUB_START_TRACK + mode, relative)

    def set_angles(self, id_list=[1, 2, 3], angle_list=[150.0, 150.0, 150.0], speed=10,  # noqa: B006
                   param=10, mode=1):
        if len(self.cur_angle_list) != len(angle_list) or list(id_list) != self._cache_ids:
            self.cur_angle_list = []
            for id_num in id_list:
                state = self.get_state(id_num=id_num)
                self.cur_angle_list.append(state[0] if self.READ_FLAG == 1 else 0)
            self._cache_ids = list(id_list)
        if len(id_list) != len(angle_list):
            return None
        if mode == 1:
            if not (speed > 0 and param > 0):
                print("speed or accel <= 0")
                return None
            delta = max(abs(a - c) for a, c in zip(angle_list, self.cur_angle_list))
            t, _ = sync_duration(delta, speed, param, self.TRAJ_MODE)
            self._presets_then_start(id_list, angle_list, t, param, mode, 0, planned=True)
        elif mode in (0, 2):
            self._presets_then_start(id_list, angle_list, speed, param, mode, 0)
        self.cur_angle_list = list(angle_list)
        return None

    def step_angle(self, id_num=1, angle=0, speed=0, param=0, mode=0):
        return self.step_angles([id_num], [angle], speed, param, mode)

    def step_angles(self, id_list=[1, 2, 3], angle_list=[150.0, 150.0, 150.0], speed=10,  # noqa: B006
                    param=10, mode=1):
        if len(id_list) != len(angle_list):
            return None
        if mode == 1:
            if not (speed > 0 and param > 0):
                print("speed or accel <= 0")
                return None
            t, _ = sync_duration(max(abs(a) for a in angle_list), speed, param, self.TRAJ_MODE)
            self._presets_then_start(id_list, angle_list, t, param, mode, 1, planned=True)
        elif mode in (0, 2):
            self._presets_then_start(id_list, angle_list, speed, param, mode, 1)
        return None

    def set_speed(self, id_num=0, speed=10, param=0, mode=1):
        values = ((speed, 0 if speed == 0 else param, INPUT_MODE_PASSTHROUGH) if mode == 1
                  else (speed, param, INPUT_MODE_VEL_RAMP))
        ok = self._frame("set_speed", id_num, lib.DARAN_CAN_TRACK + 3,
                         lib.DARAN_CAN_LAYOUT_VELOCITY, values)
        self.reply_state(id_num)
        return ok

    def set_speeds(self, id_list=[1, 2, 3], speed_list=[10.0, 20.0, 30.0], param=0, mode=1):  # noqa: B006
        if len(id_list) == len(speed_list):
            for id_num, speed in zip(id_list, speed_list):
                self.preset_speed(id_num, speed, param, mode)
            return self._system("set_speeds", 0, STARTS["MV"])
        return True

    def set_torque(self, id_num=0, torque=0.1, param=0, mode=1):
        values = ((torque, 0, INPUT_MODE_PASSTHROUGH) if mode == 1
                  else (torque, param, INPUT_MODE_TORQUE_RAMP))
        ok = self._frame("set_torque", id_num, lib.DARAN_CAN_TRACK + 4,
                         lib.DARAN_CAN_LAYOUT_TORQUE, values)
        self.reply_state(id_num)
        return ok

    def set_torques(self, id_list=[1, 2, 3], torque_list=[3.0, 4.0, 5.0], param=0, mode=1):  # noqa: B006
        if len(id_list) == len(torque_list):
            for id_num, torque in zip(id_list, torque_list):
                self.preset_torque(id_num, torque, param, mode)
            return self._system("set_torques", 0, STARTS["MC"])
        return True

    def impedance_control(self, id_num=0, pos=0, vel=0, tff=0, kp=0, kd=0):
        """A preset at the drive, then the impedance start to node 0 as the vendor sends
        it (every drive holding a preset starts: can.md C12)."""
        if self._frame("impedance_control", id_num, lib.DARAN_CAN_PRESET,
                       lib.DARAN_CAN_LAYOUT_PRESET, (pos, vel, tff)):
            self._frame("impedance_control", 0, lib.DARAN_CAN_SYSTEM, lib.DARAN_CAN_LAYOUT_GAINS,
                        (0, kp, kd), subcode=lib.DARAN_CAN_SUB_START_IMPEDANCE)
        self.reply_state(id_num)

    def estop(self, id_num=0):
        self._system("estop", id_num, SYSTEM["ST"])

    # -- settings -------------------------------------------------------------------------

    def set_id(self, id_num=0, new_id=0):
        self.write_property(id_num=id_num, property="axis0.config.can_node_id", value=new_id)
        self.save_config(id_num=new_id)

    def set_uart_baud_rate(self, id_num=0, baud_rate=115200):
        self.write_property(id_num=id_num, property="config.uart_baudrate", value=baud_rate)
        self.save_config(id_num=id_num)

    def set_can_baud_rate(self, id_num=0, baud_rate=500000):
        self.write_property(id_num=id_num, property="can.config.baud_rate", value=baud_rate)
        self.save_config(id_num=id_num)

    def set_mode(self, id_num=0, mode=2):
        if mode == 1:
            self.write_property(id_num, "axis0.requested_state", AXIS_STATE_IDLE)
        elif mode == 2:
            self.write_property(id_num, "axis0.requested_state", AXIS_STATE_CLOSED_LOOP_CONTROL)

    def set_zero_position(self, id_num=0):
        self._system("set_zero_position", id_num, SYSTEM["SZ"])

    def set_angle_range(self, id_num=0, angle_min=-360, angle_max=360):
        pos_vel = self.get_state(id_num=id_num)
        if self.READ_FLAG != 1:
            print("reading the angle failed: the range was not set")
            return False
        if not angle_min <= pos_vel[0] <= angle_max:
            print(f"the output shaft is outside {[angle_min, angle_max]}: the range was not set")
            return False
        self.write_property(id_num, "axis0.output_shaft.circular_setpoint_min", angle_min)
        self.write_property(id_num, "axis0.output_shaft.circular_setpoint_max", angle_max)
        self.write_property(id_num, "axis0.config.extra_setting.enable_circular_setpoint_limit", 1)
        self.save_config(id_num=id_num)
        return True

    def set_traj_mode(self, id_num=0, mode=1):
        self.write_property(id_num, "axis0.trap_traj.config.traj_mode", mode)
        self.TRAJ_MODE = mode

    def write_property(self, id_num=0, property="", value=0):  # noqa: A002
        prop = _vendor_property(property)
        if prop is None or prop.can == 0:
            print(f"invalid property: {property}")
            return None
        try:
            self.link.write(id_num, prop.path, prop, value)
        except (DaranError, ValueError) as exc:
            print("---error in write_property---:", exc)
            return False
        return None

    # -- reading --------------------------------------------------------------------------

    def read_property(self, id_num=0, property=""):  # noqa: A002
        if property == 0 and isinstance(property, int):
            # address 0 is the fast read: the vendor asks it with type u32 and hands its
            # status frame to reply_state, returning nothing
            data = self.link.frame_data()
            lib.daran_can_put_property(data, 0, TYPE_CODES[lib.DARAN_CLIENT_TYPE_U32], 0)
            self.link.send_frame(id_num, lib.DARAN_CAN_READ, data)
            self.reply_state(id_num)
            return None
        prop = _vendor_property(property)
        if prop is None or prop.can == 0:
            print(f"invalid property: {property}")
            return None
        try:
            type_code, raw = self.link.read_raw(id_num, prop.can, TYPE_CODES[prop.ctype],
                                                f"read {prop.path}")
        except DaranError:
            self.READ_FLAG = -1
            return None
        self.READ_FLAG = 1
        value = decode(type_code, raw)
        return value if prop.type is float else prop.type(value)

    def get_id(self, id_num=0):
        return self.read_property(id_num=id_num, property="axis0.config.can_node_id")

    def get_state(self, id_num=0):
        try:
            state = self.link.status(id_num)
        except DaranError:
            self.READ_FLAG = -1
            self.reply_state_error += 1
            return None
        self._keep_state(id_num, state)
        return [round(state.position, 2), round(state.velocity, 2)]

    def get_volcur(self, id_num=0):
        vol = self.read_property(id_num, "vbus_voltage")
        cur = self.read_property(id_num, "axis0.motor.current_control.Iq_measured")
        if self.READ_FLAG == 1 and vol is not None:
            return [round(vol, 1), round(cur, 2)]
        return None

    def get_GPIO_mode(self, id_num=0):  # noqa: N802
        enable_uart = self.read_property(id_num, "config.enable_uart")
        enable_step_dir = self.read_property(id_num, "axis0.config.enable_step_dir")
        if self.READ_FLAG == 1:
            return [enable_uart, enable_step_dir]
        return None

    # -- system ---------------------------------------------------------------------------

    def clear_error(self, id_num=0):
        self._system("clear_error", id_num, SYSTEM["SC"])

    def dump_error(self, id_num=0):
        values = [self.read_property(id_num, path) for path in _ERROR_PATHS]
        for name, value in zip(("axis", "motor", "encoder", "controller", "can",
                                "fet_thermistor", "motor_thermistor"), values):
            print(f"{name}: {value}")
        return None if None in values else sum(values)

    def save_config(self, id_num=0):
        return None if self._system("save_config", id_num, SYSTEM["SS"]) else False

    def reboot(self, id_num=0):
        return None if self._system("reboot", id_num, SYSTEM["SR"]) else False

    def position_done(self, id_num=0):
        traj_done = 0
        while not traj_done:
            traj_done = self.read_property(id_num, "axis0.controller.trajectory_done")

    def positions_done(self, id_list=[1, 2, 3]):  # noqa: B006
        for id_num in id_list:
            self.position_done(id_num)
