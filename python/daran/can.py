"""Drives on a CAN bus (the vendor's protocol, docs/can.md) over any
python-can bus. Frames are laid out by the core's CAN codec compiled into
the extension (value layouts, exact s16x100 scaling, modes, property
fields); a reply is matched to its request by node, code and address, never
taken because it came next. CAN has no error reply: a frame a drive refuses
is silent, so only queries can fail here (NoReply); a value that does not
fit its frame's field is refused before anything is sent."""
import math
import threading
import time

from ._client import ffi, lib
from ._table import BY_NAME, PROPERTIES, Result, query_properties
from .values import State
from .errors import DaranError, LinkError, NoReply
from .link import LinkAPI

#: line command -> (CAN code, layout, the values an omitted one becomes)
MOTIONS = {
    "T": (lib.DARAN_CAN_TRACK, lib.DARAN_CAN_LAYOUT_TRACK, (None, 0.0, 0.0)),
    "Q": (lib.DARAN_CAN_TRACK + 1, lib.DARAN_CAN_LAYOUT_TRAPEZOID, (None, None, None)),
    "P": (lib.DARAN_CAN_TRACK + 2, lib.DARAN_CAN_LAYOUT_PASSTHROUGH, (None, 0.0, 0.0)),
    "V": (lib.DARAN_CAN_TRACK + 3, lib.DARAN_CAN_LAYOUT_VELOCITY, (None, 0.0, 1.0)),
    "C": (lib.DARAN_CAN_TRACK + 4, lib.DARAN_CAN_LAYOUT_TORQUE, (None, 0.0, 1.0)),
    "MS": (lib.DARAN_CAN_PRESET, lib.DARAN_CAN_LAYOUT_PRESET, (None, None, None)),
}
#: start command -> its sub-code (the shapes' order, as the codec has it)
STARTS = {name: lib.DARAN_CAN_SUB_START_TRACK + i
          for i, name in enumerate(("MT", "MQ", "MP", "MV", "MC"))}
#: system command -> its sub-code (the HAL actions' order from SAVE; `u` is the library's own)
SYSTEM = {name: lib.DARAN_CAN_SUB_SAVE + i
          for i, name in enumerate(("SS", "SE", "SR", "SC", "SZ", "ST"))}
SYSTEM["U"] = lib.DARAN_CAN_SUB_FEED
#: a property's type on the bus: f32 rows as f32, s32 as s32, u32 and bool as u32 (can.md)
TYPE_CODES = {lib.DARAN_CLIENT_TYPE_F32: lib.DARAN_CAN_TYPE_F32,
              lib.DARAN_CLIENT_TYPE_S32: lib.DARAN_CAN_TYPE_S32,
              lib.DARAN_CLIENT_TYPE_U32: lib.DARAN_CAN_TYPE_U32,
              lib.DARAN_CLIENT_TYPE_BOOL: lib.DARAN_CAN_TYPE_U32}
_SERIAL = ("SERIAL_NUMBER_L", "SERIAL_NUMBER_H")
#: can.md: a receiver takes any odd code below 0x18 as a status frame (no command code is one)
_STATUS_BELOW = 0x18
#: what `q` with its velocity or acceleration left out sends instead, read first (C37)
_TRAPEZOID_LIMITS = ("output_shaft.trap_traj_vel_limit", "output_shaft.trap_traj_accel_limit")


class CanLink(LinkAPI):
    """Drives on a python-can bus: `daran.open_can(bus)`. Options as daran.open's
    (timeout per reply, retries of queries); `confirm` and `checksum` do not apply."""

    def __init__(self, bus, *, timeout=0.05, retries=1, **_line_options):
        import can  # imported here: `import daran` stays fast
        self._can = can
        self.bus = bus
        self.timeout = timeout
        self.retries = retries
        self._lock = threading.RLock()
        self._data = ffi.new("uint8_t[8]")
        self._values = ffi.new("float[3]")
        self.closed = False
        #: CAN carries no telemetry reports; kept for LinkAPI.telemetry()
        self.reports = []
        #: frames that answered no request (late replies, status frames, heartbeats)
        self.unmatched = 0

    # -- frames -----------------------------------------------------------------------------

    def send_frame(self, node, code, data):
        """One 8-byte frame (data: the codec's uint8_t[8]) to `node` with `code`."""
        self._send(node, code, data)

    def _send(self, node, code, data):
        if self.closed:
            raise LinkError(Result.ERR_BUS_ERROR, "the link is closed")
        message = self._can.Message(arbitration_id=node << 5 | code, is_extended_id=False,
                                    data=bytes(ffi.buffer(data, 8)))
        try:
            self.bus.send(message, timeout=self.timeout)
        except self._can.CanError as exc:
            raise LinkError(Result.ERR_BUS_ERROR, f"send: {exc}") from exc

    def _drain(self):
        """Drop what came before a request: a late reply is never the next one's."""
        while self.bus.recv(0) is not None:
            self.unmatched += 1

    def _await(self, match, timeout):
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            message = self.bus.recv(left)
            if message is None:
                return None
            if (not message.is_extended_id and not message.is_remote_frame and message.dlc == 8
                    and match(message)):
                return message
            self.unmatched += 1

    def frame_data(self):
        """A zeroed frame buffer for send_frame."""
        return self._data_of()

    def _data_of(self):
        """The frame buffer, zeroed: bytes a frame does not use are sent as 0."""
        ffi.memmove(self._data, bytes(8), 8)
        return self._data

    def read_raw(self, node, address, type_code, what):
        """One 0x01E read of `address` at `node` (0: the one drive on the bus answers),
        the property's type code in bytes 2..3 as the vendor's libraries put it (drives
        do not read it, C7): (the reply's type code, its value bytes). Sent again after
        a timeout up to `retries` times (a read has no effect)."""
        read_code = lib.DARAN_CAN_READ
        data = self._data_of()
        lib.daran_can_put_property(data, address, type_code, 0)

        def match(message):
            return ((message.arbitration_id & 0x1F) == read_code
                    and (node == 0 or message.arbitration_id >> 5 == node)
                    and lib.daran_can_get_u16(_view(message.data)) == address
                    and lib.daran_can_get_u16(_view(message.data) + 2) <= lib.DARAN_CAN_TYPE_S32)

        with self._lock:
            for _ in range(self.retries + 1):
                self._drain()
                self._send(node, lib.DARAN_CAN_READ, data)
                reply = self._await(match, self.timeout)
                if reply is not None:
                    return lib.daran_can_get_u16(_view(reply.data) + 2), bytes(reply.data[4:8])
        raise NoReply(Result.ERR_NO_REPLY, what)

    def _read_value(self, node, prop):
        if prop.can == 0 and prop.name == "SERIAL_NUMBER":
            low, high = (self._read_value(node, BY_NAME[name]) for name in _SERIAL)
            return high << 32 | low
        if prop.can == 0:
            raise DaranError(Result.ERR_NOT_BRIDGED, f"{prop.path} has no CAN address")
        type_code, raw = self.read_raw(node, prop.can, TYPE_CODES[prop.ctype],
                                       f"read {prop.path} (node {node})")
        value = decode(type_code, raw)
        return prop.type(value) if prop.type is not float else float(value)

    # -- what a Drive asks of its link --------------------------------------------------------

    def command(self, command, drive_id, values, wait=None):
        data = self._data_of()
        if command == "Q" and 1 <= len(values) < 3:  # as a gateway does: the drive's limits
            values = list(values) + [self.read(drive_id, path, PROPERTIES[path])
                                     for path in _TRAPEZOID_LIMITS[len(values) - 1:]]
            data = self._data_of()
        if command in MOTIONS:
            code, layout, defaults = MOTIONS[command]
            self._encode(layout, _complete(command, values, defaults), data)
            self._send(drive_id, code, data)
        elif command == "D":  # a preset, then its impedance start at the same node (C12)
            self._encode(lib.DARAN_CAN_LAYOUT_PRESET, values[:3], data)
            self._send(drive_id, lib.DARAN_CAN_PRESET, data)
            data = self._data_of()
            self._encode(lib.DARAN_CAN_LAYOUT_GAINS, (0.0, values[3], values[4]), data)
            lib.daran_can_put_u32(data, lib.DARAN_CAN_SUB_START_IMPEDANCE)
            self._send(drive_id, lib.DARAN_CAN_SYSTEM, data)
        elif command in STARTS:
            lib.daran_can_put_u32(data, STARTS[command])
            if values:
                lib.daran_can_put_u16(data + 4, int(values[0]))
            self._send(drive_id, lib.DARAN_CAN_SYSTEM, data)
        elif command in SYSTEM:
            lib.daran_can_put_u32(data, SYSTEM[command])
            self._send(drive_id, lib.DARAN_CAN_SYSTEM, data)
        else:
            raise DaranError(Result.ERR_NOT_BRIDGED, f"{command}: no CAN form")

    def encode(self, layout, values, data):
        """The codec's layout of three values into data; refused (nothing sent) when a
        value is not finite or does not fit its s16x100 field."""
        self._encode(layout, values, data)

    def _encode(self, layout, values, data):
        for v in values:
            if not math.isfinite(v):
                raise DaranError(Result.ERR_INVALID_VALUE, f"{v}: not finite")
        self._values[0:3] = list(values)
        if not lib.daran_can_encode_values(layout, self._values, data):
            raise DaranError(Result.ERR_OUT_OF_RANGE,
                             f"{list(values)}: beyond the frame's s16x100 field")

    def query(self, command, drive_id, expected, types):
        _unicast(drive_id)
        return [self._read_value(drive_id, prop) for prop in query_properties(command)]

    def read(self, drive_id, path, prop):
        _unicast(drive_id)
        if prop is None:
            raise DaranError(Result.ERR_INVALID_PROPERTY, f"{path}: not in the table")
        return self._read_value(drive_id, prop)

    def read_text(self, drive_id, prop):
        """A property's value printed as the drive prints it (the core's number printer)."""
        from .dump import format_value
        return format_value(prop, self.read(drive_id, prop.path, prop))

    def write(self, drive_id, path, prop, value, wait=None):
        if prop is None or prop.can == 0:
            raise DaranError(Result.ERR_INVALID_PROPERTY if prop is None else Result.ERR_NOT_BRIDGED,
                             f"{path}: no CAN address")
        data = self._data_of()
        if prop.ctype == lib.DARAN_CLIENT_TYPE_F32:
            bits = ffi.new("uint8_t[4]")
            lib.daran_can_put_f32(bits, float(value))
            lib.daran_can_put_property(data, prop.can, lib.DARAN_CAN_TYPE_F32,
                                       lib.daran_can_get_u32(bits))
        else:
            if isinstance(value, float) and not value.is_integer():
                raise ValueError(f"{value!r}: {prop.path} takes an integer")
            lib.daran_can_put_property(data, prop.can, TYPE_CODES[prop.ctype],
                                       int(value) & 0xFFFFFFFF)
        self._send(drive_id, lib.DARAN_CAN_WRITE, data)

    def state(self, drive_id):
        """The fast read (address 0): the status frame's position, velocity, torque
        estimate, T (trajectory done) and E (an error) bits."""
        _unicast(drive_id)
        return self.status(drive_id, read=True)

    def status(self, drive_id, read=True, timeout=None):
        """A status frame of `drive_id` (0: any drive): asked for with the fast read, or
        (read=False) the one a motion frame makes with enable_reply_state."""
        data = self._data_of()
        lib.daran_can_put_property(data, 0, 0, 0)

        def match(message):
            code = message.arbitration_id & 0x1F
            return ((drive_id == 0 or message.arbitration_id >> 5 == drive_id)
                    and code & lib.DARAN_CAN_STATUS and code < _STATUS_BELOW)

        with self._lock:
            for _ in range(self.retries + 1 if read else 1):
                if read:
                    self._drain()
                    self._send(drive_id, lib.DARAN_CAN_READ, data)
                reply = self._await(match, self.timeout if timeout is None else timeout)
                if reply is not None:
                    code = reply.arbitration_id & 0x1F
                    raw = _view(reply.data)
                    return State(float(lib.daran_can_get_f32(raw)),
                                 float(lib.daran_can_get_scaled(raw + 4)),
                                 float(lib.daran_can_get_scaled(raw + 6)),
                                 bool(code >> 1 & 1), code >> 2 & 1)
        raise NoReply(Result.ERR_NO_REPLY, f"fast read (node {drive_id})")

    def error_registers(self, drive_id):
        return self.query("E", drive_id, 7, None)

    def discover(self, drive_id, prefix=None):
        raise DaranError(Result.ERR_NOT_BRIDGED, "discovery has no CAN form: the built-in table")

    def service(self):
        self._drain()

    def wait_input(self, seconds):
        time.sleep(seconds)

    def close(self):
        if not self.closed:
            self.closed = True
            self.bus.shutdown()
        if self.sim is not None:
            self.sim.close()


def decode(type_code, raw):
    """A read reply's value by its own type code (can.md: 0 f32, 1 u16, 2 s16, 3 u32, 4 s32)."""
    raw = _view(raw)
    if type_code == lib.DARAN_CAN_TYPE_F32:
        return float(lib.daran_can_get_f32(raw))
    if type_code == lib.DARAN_CAN_TYPE_U16:
        return lib.daran_can_get_u16(raw)
    if type_code == lib.DARAN_CAN_TYPE_S16:
        value = lib.daran_can_get_u16(raw)
        return value - 0x10000 if value & 0x8000 else value
    value = lib.daran_can_get_u32(raw)
    if type_code == lib.DARAN_CAN_TYPE_S32 and value & 0x80000000:
        return value - 0x100000000
    return value


def _view(data):
    """A received frame's bytes as the codec's uint8_t *."""
    return ffi.from_buffer("uint8_t[]", data)


def _complete(command, values, defaults):
    values = list(values) + [None] * (3 - len(values))
    out = [given if given is not None else default for given, default in zip(values, defaults)]
    if None in out:
        raise ValueError(f"{command}: every value is needed on CAN (the drive has no default "
                         "for an omitted field here)")
    return out


def _unicast(drive_id):
    if not 1 <= drive_id <= 63:
        raise ValueError(f"drive {drive_id}: a query goes to one drive, 1..63 (every drive "
                         "answers a broadcast read)")
