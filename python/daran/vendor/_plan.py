"""The vendor libraries' timing rule for synchronised trapezoids, shared by
daran.vendor and daran.vendor.can: the duration that brings the largest move
`delta` (deg) to rest with cruise `speed` (r/min) and `accel` ((r/min)/s),
for a trapezoidal (traj_mode 1) or an S-curve (2) velocity profile. 6 turns
r/min into deg/s."""
import math


def sync_duration(delta, speed, accel, traj_mode=1):
    """(duration s, the speed actually reached) for the move."""
    accel = abs(accel)
    if traj_mode == 2:
        if delta <= 12 * speed * speed / accel:
            speed = math.sqrt(accel * delta / 12)
            return 4 * speed / accel, speed
        return delta / (6 * speed) + 2 * speed / accel, speed
    if delta <= 6 * speed * speed / accel:
        return 2 * math.sqrt(delta / (6 * accel)), speed
    return speed / accel + delta / (6 * speed), speed
