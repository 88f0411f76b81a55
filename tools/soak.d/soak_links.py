"""The three clients' ways to a drive, each as a real client speaks:

- AsciiPath: lines on daran-sim's ASCII pseudo-terminal, as the vendor's
  DrEmpower_ascii.py writes them (a trailing space, a checksum `*N` on some
  lines); for drive 1 they are answered by it, for drives 2 and 3 they cross
  the CAN bus through drive 1's bridge. The pty is shared by two clients:
  one exchange at a time holds its lock.
- CanPath: the vendor's CAN frames (../shared/spec/can.md) through python-can's
  slcan interface; every reply is matched by node, code and address, never
  taken as the next frame (the bus also carries the bridge's traffic).

Every call is timed and counted in Stats; a call that gets no answer raises
NoAnswer with its cause, a dead link LinkDown."""
import struct
import threading
import time

PROPERTIES = (
    # (path under axisN., type, CAN address); stored config with no physics,
    # so values written by the soak change nothing else the soak checks
    ("config.calibration_lockin.current", "f32", 31101),
    ("config.calibration_lockin.ramp_time", "f32", 31102),
    ("config.calibration_lockin.accel", "f32", 31104),
    ("config.calibration_lockin.vel", "f32", 31105),
    ("controller.config.gain_scheduling_width", "f32", 32107),
    ("config.extra_setting.stored_turns_counts", "s32", 31206),
    ("config.extra_setting.enable_adaptive_gain", "bool", 31212),
)
TYPE_CODE = {"f32": 0, "u32": 3, "bool": 3, "s32": 4}
TRAJECTORY_DONE = 32008
FAST_READ = 0


class NoAnswer(Exception):
    """A call without its answer; .cause names why (counted by cause)."""

    def __init__(self, cause):
        super().__init__(cause)
        self.cause = cause


class LinkDown(Exception):
    """The pseudo-terminal is gone (daran-sim died or is being restarted)."""


def f32(value):
    """@value rounded to float32, as the drive stores it."""
    return struct.unpack("<f", struct.pack("<f", value))[0]


def same_value(kind, a, b):
    if a is None or b is None:
        return a is b
    if kind == "f32":
        return struct.pack("<f", a) == struct.pack("<f", b)
    return int(a) == int(b)


def shown(value):
    """@value as its shortest decimal that reads back as the same float32
    (what the drive prints); integers as they are."""
    if isinstance(value, float):
        for digits in range(1, 10):
            text = "%.*g" % (digits, value)
            if same_value("f32", float(text), value):
                return text
    return repr(value)


def text_of(kind, value):
    if kind == "f32":
        return repr(f32(value))
    return str(int(value))


def parse_value(kind, text):
    return f32(float(text)) if kind == "f32" else int(text)


def xor_of(text):
    acc = 0
    for byte in text.encode("ascii"):
        acc ^= byte
    return acc


class AsciiLink:
    """The ASCII pseudo-terminal, opened by pyserial (reopened after a restart)."""

    REPLY_TIMEOUT = 5.0   # a line is always answered: the bridge gives up after 10 ms

    def __init__(self, serial_module, stats, rng):
        self.serial = serial_module
        self.stats = stats
        self.rng = rng
        self.port = None
        self.lock = threading.RLock()

    def open(self, path):
        with self.lock:
            self.close()
            self.port = self.serial.Serial(path, 115200, timeout=self.REPLY_TIMEOUT)

    def close(self):
        with self.lock:
            if self.port is not None:
                try:
                    self.port.close()
                except OSError:
                    pass
                self.port = None

    def _line(self, text):
        """@text as the vendor's library sends it: a trailing space, and on
        about a third of the lines its checksum."""
        line = text + " "
        if self.rng.random() < 0.33:
            return line + "*%d" % xor_of(line), True
        return line, False

    def query(self, client, text):
        """One query line and its one reply line (checked, without its
        checksum). Timed as a call of @client."""
        with self.lock:
            line, checksummed = self._line(text)
            self.stats.trace("%s: > %s" % (client, line))
            started = self._write(line)
            reply = self._checked(self._read_line(), checksummed)
            self.stats.call(client, time.monotonic() - started)
        return reply

    def command(self, client, text):
        """A line answered only when it fails, followed by a fence (`i 1`,
        always answered by drive 1 itself) so that its error, if any, is
        told from later replies. Its error line, or None."""
        with self.lock:
            line, checksummed = self._line(text)
            fence, fence_checksummed = self._line("i 1")
            self.stats.trace("%s: > %s (+ fence)" % (client, line))
            started = self._write(line + "\n" + fence)
            first = self._read_line()
            error = None
            if first.startswith("error:"):
                error = self._checked(first, checksummed)
                first = self._read_line()
            fence_reply = self._checked(first, fence_checksummed)
            if len(fence_reply.split()) != 3:
                self._resync()
                raise NoAnswer("pty: unexpected reply %r to the fence" % fence_reply)
            self.stats.call(client, time.monotonic() - started)
        return error

    def send_only(self, client, text):
        """A line written and not waited for (the kill -9 that follows
        must catch the drive busy with it)."""
        with self.lock:
            line, _ = self._line(text)
            self.stats.trace("%s: > %s (not waited for)" % (client, line))
            self._write(line)

    def _write(self, text):
        if self.port is None:
            raise LinkDown("ASCII pty closed")
        try:
            self.port.write((text + "\n").encode("ascii"))
        except (OSError, self.serial.SerialException) as err:
            raise LinkDown("ASCII pty: %s" % err)
        return time.monotonic()

    def _read_line(self):
        try:
            raw = self.port.readline()
        except (OSError, self.serial.SerialException) as err:
            raise LinkDown("ASCII pty: %s" % err)
        if not raw.endswith(b"\n"):
            self._resync()
            raise NoAnswer("pty: line unanswered")
        reply = raw.decode("ascii", errors="replace").rstrip("\r\n")
        self.stats.trace("   < %s" % reply)
        return reply

    def _checked(self, text, checksummed):
        """@text's payload; its checksum is there exactly when the request
        had one, and right."""
        payload, star, digits = text.rpartition(" *")
        has_sum = bool(star) and digits.isdigit()
        if has_sum != checksummed or (has_sum and xor_of(payload + " ") != int(digits)):
            self._resync()
            raise NoAnswer("pty: reply %r to a line %s a checksum" %
                           (text, "with" if checksummed else "without"))
        return payload if has_sum else text

    def _resync(self):
        # an answer that comes after all must not be taken for the next one
        try:
            self.port.timeout = 0.3
            while self.port.readline():
                pass
            self.port.timeout = self.REPLY_TIMEOUT
        except (OSError, self.serial.SerialException) as err:
            raise LinkDown("ASCII pty: %s" % err)


class AsciiPath:
    """Drive @drive through the ASCII link: itself (1) or through the bridge."""

    def __init__(self, link, client, drive):
        self.link = link
        self.client = client
        self.drive = drive

    def _query(self, text):
        reply = self.link.query(self.client, text)
        if reply.startswith("error:"):
            raise NoAnswer(reply)
        return reply

    def _command(self, text):
        error = self.link.command(self.client, text)
        if error is not None:
            raise NoAnswer(error)

    def read(self, name, kind):
        reply = self._query("r axis%d.%s" % (self.drive, name))
        try:
            return parse_value(kind, reply)
        except ValueError:
            raise NoAnswer("not a value: %r" % reply)

    def write(self, name, kind, value):
        self._command("w axis%d.%s %s" % (self.drive, name, text_of(kind, value)))

    def save(self):
        self._command("ss %d" % self.drive)

    def save_unwaited(self):
        self.link.send_only(self.client, "ss %d" % self.drive)

    def move_to(self, target, vel, acc):
        self._command("q %d %s %s %s" % (self.drive, repr(f32(target)), vel, acc))

    def move_by(self, distance, duration, acc):
        self._command("ms %d %s %s %s" % (self.drive, repr(f32(distance)), duration, acc))
        self._command("mq %d 1" % self.drive)

    def state(self):
        """(position in degrees, trajectory done)."""
        done = self._query("r axis%d.controller.trajectory_done" % self.drive)
        reply = self._query("f %d" % self.drive)
        try:
            return float(reply.split()[0]), done == "1"
        except (ValueError, IndexError):
            raise NoAnswer("not a position: %r" % reply)


class CanLink:
    """python-can's slcan interface on daran-sim's slcan pseudo-terminal."""

    TIMEOUT = 0.25   # a drive answers within a few ms; a loaded host may be slow

    def __init__(self, can_module, stats):
        self.can = can_module
        self.stats = stats
        self.bus = None
        self.lock = threading.RLock()
        self.foreign_frames = 0

    def open(self, path):
        with self.lock:
            self.close()
            self.bus = self.can.Bus(interface="slcan", channel=path, bitrate=1000000,
                                    sleep_after_open=0.05)

    def close(self):
        with self.lock:
            if self.bus is not None:
                try:
                    self.bus.shutdown()
                except Exception:  # a dead pty: python-can raises its own kinds
                    pass
                self.bus = None

    def send(self, ident, data):
        if self.bus is None:
            raise LinkDown("slcan closed")
        self.stats.trace("can: > %03X %s" % (ident, bytes(data).hex()))
        try:
            self.bus.send(self.can.Message(arbitration_id=ident, is_extended_id=False,
                                           data=data))
        except (self.can.CanError, OSError) as err:
            raise LinkDown("slcan: %s" % err)

    def drain(self, wait=0.02):
        """Frames that came while nobody asked: late replies to requests
        that a fault held back (an unplugged adapter sends its queue when
        plugged in again). A status frame names no request: taken for the
        next request's answer, it would be one behind from then on."""
        with self.lock:
            while self._recv(wait) is not None:
                self.foreign_frames += 1

    def _recv(self, timeout):
        try:
            return self.bus.recv(timeout)
        except (self.can.CanError, OSError, ValueError, IndexError) as err:
            raise LinkDown("slcan: %s" % err)

    def request(self, client, ident, data, matches):
        """@data sent at @ident; the first frame for which @matches(msg) is
        true, within TIMEOUT, as (id, data); every other frame is someone
        else's."""
        with self.lock:
            self.drain(0.0)
            started = time.monotonic()
            self.send(ident, data)
            deadline = started + self.TIMEOUT
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise NoAnswer("CAN: no reply within %d ms" % (self.TIMEOUT * 1000))
                msg = self._recv(left)
                if msg is None:
                    continue
                if not msg.is_extended_id and msg.dlc == 8 and matches(msg):
                    self.stats.trace("can: < %03X %s" % (msg.arbitration_id, bytes(msg.data).hex()))
                    self.stats.call(client, time.monotonic() - started)
                    return msg.arbitration_id, bytes(msg.data)
                self.foreign_frames += 1

    def command(self, client, ident, data):
        """A frame the drive never answers (a write, a motion, a system command)."""
        with self.lock:
            started = time.monotonic()
            self.send(ident, data)
            self.stats.call(client, time.monotonic() - started)


class CanPath:
    """Drive @drive (its node id) through the CAN link, the vendor's frames."""

    def __init__(self, link, client, drive):
        self.link = link
        self.client = client
        self.node = drive
        self.drive = drive

    def _id(self, code):
        return self.node << 5 | code

    def read(self, name, kind):
        address = next(a for n, _, a in PROPERTIES if n == name)
        reply_id = self._id(0x1E)
        _, data = self.link.request(
            self.client, reply_id, struct.pack("<HHI", address, TYPE_CODE[kind], 0),
            lambda m: m.arbitration_id == reply_id and m.data[0] | m.data[1] << 8 == address)
        code = struct.unpack_from("<H", data, 2)[0]
        if code == 0:
            return f32(struct.unpack_from("<f", data, 4)[0])
        if code == 4:
            return struct.unpack_from("<i", data, 4)[0]
        return struct.unpack_from("<I", data, 4)[0]

    def write(self, name, kind, value):
        address = next(a for n, _, a in PROPERTIES if n == name)
        if kind == "f32":
            raw = struct.pack("<f", value)
        elif kind == "s32":
            raw = struct.pack("<i", int(value))
        else:
            raw = struct.pack("<I", int(value))
        self.link.command(self.client, self._id(0x1F),
                          struct.pack("<HH", address, TYPE_CODE[kind]) + raw)

    def save(self):
        self.link.command(self.client, self._id(0x08), struct.pack("<IHH", 0x01, 0, 0))

    save_unwaited = save    # a frame is never answered

    def move_to(self, target, vel, acc):
        self.link.command(self.client, self._id(0x1A),
                          struct.pack("<fhh", target, round(vel * 100), round(acc * 100)))

    def move_by(self, distance, duration, acc):
        # the vendor's step_angle: a preset, then a relative timed start (at
        # this node rather than the library's node 0, which would also start
        # presets the other clients hold)
        self.link.command(self.client, self._id(0x0C),
                          struct.pack("<fhh", distance, round(duration * 100), round(acc * 100)))
        self.link.command(self.client, self._id(0x08), struct.pack("<IHH", 0x11, 1, 0))

    def state(self):
        """(position, trajectory done) from one fast read's status frame."""
        node = self.node
        ident, data = self.link.request(
            self.client, self._id(0x1E), bytes(8),
            lambda m: m.arbitration_id >> 5 == node and m.arbitration_id & 0x19 == 0x01)
        return struct.unpack_from("<f", data, 0)[0], bool(ident & 0x02)
