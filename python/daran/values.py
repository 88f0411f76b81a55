"""What a drive's reads come back as: plain values, imported by the links
and by Drive alike (so neither imports the other)."""
from typing import NamedTuple


class State(NamedTuple):
    """What `state()` reads: the output shaft's position (deg), velocity (r/min)
    and torque estimate (Nm), whether the trajectory is done, and the error:
    `axis0.error` on a line, the status frame's E bit (1 when axis0.error is
    not 0) on CAN."""
    position: float
    velocity: float
    torque: float
    done: bool
    error: int


class Errors(NamedTuple):
    """`e`'s seven registers (axis, motor, encoder, controller,
    fet_thermistor, motor_thermistor, can) and the vendor's names of the bits set."""
    registers: dict
    names: dict

    def __bool__(self):
        return any(self.registers.values())
