"""A drive on a link: a method for every command, its properties as an
attribute tree, its state and its errors."""
from ._client import lib
from ._link import lookup
from ._table import ERROR_REGISTERS, PROPERTIES, Property, error_bit_name
from .props import PropertyTree
from .values import Errors, State




#: the bits of `axis0.telemetry.fields`, in order (protocol.md 11.2)
TELEMETRY_FIELDS = ("position", "velocity", "torque", "iq", "vbus", "fet_temperature",
                    "motor_temperature", "error", "done")

#: start kind -> (its start command, whether it takes the relative flag)
STARTS = {"filtered": ("MT", True), "trapezoid": ("MQ", True), "passthrough": ("MP", True),
          "velocity": ("MV", False), "torque": ("MC", False)}

_F = (lib.DARAN_CLIENT_TYPE_F32,) * 2
_I = (lib.DARAN_CLIENT_TYPE_U32, lib.DARAN_CLIENT_TYPE_U32, lib.DARAN_CLIENT_TYPE_U64)


class Drive:
    """Drive `id` on a link (0: every drive, for commands)."""

    def __init__(self, link, drive_id):
        if not 0 <= drive_id <= lib.DARAN_CLIENT_ID_MAX:
            raise ValueError(f"drive id {drive_id}: 0..{lib.DARAN_CLIENT_ID_MAX}")
        self.link = link
        self.id = drive_id
        self._table = PROPERTIES
        self.props = PropertyTree(self, self._table)
        self._props = {}  # path -> its Property, looked up once

    def __repr__(self):
        return f"<daran.Drive {self.id}>"

    # -- motion (silent commands: a refusal raises DriveRefused; never retried) -------------

    def _send(self, command, *values, wait=None):
        self.link.command(command, self.id, values, wait)

    def move_to(self, position, bandwidth=None, *, wait=None):
        """`t`: follow `position` (deg) through the input filter of `bandwidth` 1/s
        (None keeps the drive's). `t`'s velocity field is read by no drive: sent as 0."""
        self._send("T", *((position,) if bandwidth is None else (position, 0, bandwidth)),
                   wait=wait)

    def trapezoid(self, position, velocity=None, acceleration=None, *, wait=None):
        """`q`: a trapezoid to `position` (deg) at `velocity` r/min, `acceleration` (r/min)/s."""
        self._send("Q", *_given(position, velocity, acceleration), wait=wait)

    def position(self, position, velocity_ff=None, torque_ff=None, *, wait=None):
        """`p`: position with velocity and torque feed-forward."""
        self._send("P", *_given(position, velocity_ff, torque_ff), wait=wait)

    def velocity(self, velocity, param=None, mode=None, *, wait=None):
        """`v`: velocity (r/min); mode 1 param = torque feed-forward, mode 2 param = ramp rate."""
        self._send("V", *_given(velocity, param, mode), wait=wait)

    def torque(self, torque, param=None, mode=None, *, wait=None):
        """`c`: torque (Nm); mode 1 at once, mode 6 (or 2) ramped at param Nm/s."""
        self._send("C", *_given(torque, param, mode), wait=wait)

    def impedance(self, position, velocity, torque_ff, kp, kd, *, wait=None):
        """`d`: impedance control around position (deg) and velocity (r/min)."""
        self._send("D", position, velocity, torque_ff, kp, kd, wait=wait)

    def preset(self, p1, p2, p3, *, wait=None):
        """`ms`: store a preset for a later start (link.start or link.move_together)."""
        self._send("MS", p1, p2, p3, wait=wait)

    def start(self, kind, relative=False, *, wait=None):
        """Start this drive's preset as `kind` (see STARTS)."""
        command, takes_flag = STARTS[kind]
        self._send(command, *((1 if relative else 0,) if takes_flag else ()), wait=wait)

    # -- system ---------------------------------------------------------------------------

    def estop(self, *, wait=None):
        self._send("ST", wait=wait)

    def clear_errors(self, *, wait=None):
        self._send("SC", wait=wait)

    def save(self, *, wait=None):
        self._send("SS", wait=wait)

    def erase_config(self, *, wait=None):
        self._send("SE", wait=wait)

    def reboot(self, *, wait=None):
        self._send("SR", wait=wait)

    def set_zero(self, *, wait=None):
        self._send("SZ", wait=wait)

    def enable(self, *, wait=None):
        """Closed-loop control (`requested_state` 8), as after an e-stop was cleared."""
        self.set("requested_state", 8, wait=wait)

    def disable(self, *, wait=None):
        """Idle (`requested_state` 1): the motor delivers no torque."""
        self.set("requested_state", 1, wait=wait)

    def feed_watchdog(self, *, wait=None):
        self._send("U", wait=wait)

    # -- telemetry (a line link: protocol.md 11.2) ----------------------------------------

    def stream(self, period, fields=("position", "velocity")):
        """Make the drive send a telemetry report every `period` s with `fields` (in
        TELEMETRY_FIELDS' order in the report); link.telemetry() yields them."""
        mask = 0
        for name in fields:
            mask |= 1 << TELEMETRY_FIELDS.index(name)
        self.set("telemetry.fields", mask)
        self.set("telemetry.period", period)

    def stop_stream(self):
        self.set("telemetry.period", 0)

    # -- queries --------------------------------------------------------------------------

    def position_velocity(self):
        """`f`: (position deg, velocity r/min)."""
        return tuple(self.link.query("F", self.id, 2, _F))

    def voltage_current(self):
        """`g`: (bus voltage V, current A)."""
        return tuple(self.link.query("G", self.id, 2, _F))

    def info(self):
        """`i`: (firmware version, hardware version, serial number)."""
        return tuple(self.link.query("I", self.id, 3, _I))

    def state(self):
        """A State: position, velocity, torque, trajectory done, error (one round trip)."""
        return self.link.state(self.id)

    def errors(self):
        """`e`: the seven registers and the vendor's names of their bits that are set."""
        registers, names = {}, {}
        for index, (register, value) in enumerate(zip(ERROR_REGISTERS,
                                                      self.link.error_registers(self.id))):
            registers[register] = value
            names[register] = [error_bit_name(index, bit) for bit in range(32) if value >> bit & 1]
        return Errors(registers, names)

    # -- properties -----------------------------------------------------------------------

    def property(self, path):
        """The Property of `path` (with or without `axisN.`), from the drive's table."""
        prop = lookup(path, self._table)
        if prop is None:
            raise KeyError(path)
        return prop

    def get(self, path):
        """Read a property (`r`) as its type."""
        prop = self._props.get(path)
        if prop is None:
            prop = self._props[path] = lookup(path, self._table)
        return self.link.read(self.id, path, prop)

    def set(self, path, value, *, wait=None):
        """Write a property (`w`), its value sent as the property's type."""
        self.link.write(self.id, path, lookup(path, self._table), value, wait)

    def dump(self, file=None):
        """The drive's configuration in the CLI's dump format (`daran dump`): returned,
        and written to `file` (a path) when given."""
        from .dump import dump
        text = dump(self, "the drive's discovery" if self._table is not PROPERTIES
                    else "the vendor table")
        if file is not None:
            with open(file, "w") as out:
                out.write(text)
        return text

    def restore(self, file, save=False, force=False):
        """Write a dump file into this drive (`daran restore`); returns the lines whose
        value the drive keeps otherwise, as (line, path, file value, kept value)."""
        from .dump import restore
        return restore(self, file, save, force)

    def discover(self, prefix=None):
        """Read the drive's own property table (`h id properties`) and use it from now on
        for types and the props tree; returns it. Drives without discovery refuse it."""
        self._table = self.link.discover(self.id, prefix)
        self.props = PropertyTree(self, self._table)
        self._props = {}
        return self._table


def _given(*values):
    """The values up to the last one given: optional fields are left off the line."""
    values = list(values)
    while values and values[-1] is None:
        values.pop()
    if None in values:
        raise ValueError("an optional value may be left out only after the ones given")
    return values


__all__ = ["Drive", "State", "Errors", "Property", "STARTS"]
