"""A link to drives over a line transport, through the C client's link
(daran_client_transact): the C code builds each request, collects and
checks its reply, applies the retry rule (queries only) and hands telemetry
reports and stray lines over; Python gives it the bytes (a transport object
with write(bytes) -> bool, read(size, timeout_ms) -> bytes, close())."""
import collections
import threading
import time
from typing import NamedTuple

from ._client import ffi, lib
from ._table import COMMANDS, PROPERTIES, Property, Result
from .errors import DriveRefused, LinkError, NoReply, raise_for
from .values import State

SCOPE = {None: lib.DARAN_CLIENT_SCOPE_AUTO, False: lib.DARAN_CLIENT_SCOPE_AXIS,
         True: lib.DARAN_CLIENT_SCOPE_SYSTEM}


class Report(NamedTuple):
    """A telemetry report: the drive's id, its time (s), the values in the
    order of the bits of `axis0.telemetry.fields`."""
    id: int
    time: float
    values: tuple


class Line(NamedTuple):
    """A reply line: its kind (lib.DARAN_CLIENT_LINE_*) and payload text."""
    kind: int
    text: str


def number_value(number, ctype=None):
    """A daran_client_number_t * as the Python value of its type (int, float,
    bool); the C client converted it, here only the type is chosen."""
    if ctype is None:
        if not number.is_integer:
            return float(number.f32)
        return -number.magnitude if number.negative else number.magnitude
    if ctype == lib.DARAN_CLIENT_TYPE_F32:
        return float(number.f32)
    out = _NUMBER_OUT[ctype]
    result = _NUMBER_CONVERT[ctype](number, out)
    if result != Result.OK:
        raise LinkError(result, "reply value does not fit its type")
    return bool(out[0]) if ctype == lib.DARAN_CLIENT_TYPE_BOOL else int(out[0])


_NUMBER_OUT = {lib.DARAN_CLIENT_TYPE_U32: ffi.new("uint32_t[1]"),
               lib.DARAN_CLIENT_TYPE_BOOL: ffi.new("uint32_t[1]"),
               lib.DARAN_CLIENT_TYPE_S32: ffi.new("int32_t[1]"),
               lib.DARAN_CLIENT_TYPE_U64: ffi.new("uint64_t[1]")}
_NUMBER_CONVERT = {lib.DARAN_CLIENT_TYPE_U32: lib.daran_client_number_u32,
                   lib.DARAN_CLIENT_TYPE_BOOL: lib.daran_client_number_u32,
                   lib.DARAN_CLIENT_TYPE_S32: lib.daran_client_number_s32,
                   lib.DARAN_CLIENT_TYPE_U64: lib.daran_client_number_u64}


@ffi.def_extern()
def daran_py_write(ctx, data, length):
    link = ffi.from_handle(ctx)
    try:
        return bool(link._transport.write(ffi.buffer(data, length)[:]))
    except Exception as exc:  # the C link sees a refused write; the caller the cause
        link._callback_error = exc
        return False


@ffi.def_extern()
def daran_py_read(ctx, buf, size, timeout_ms):
    link = ffi.from_handle(ctx)
    try:
        data = link._transport.read(size, timeout_ms)
    except Exception as exc:
        link._callback_error = exc
        return 0
    ffi.memmove(buf, data, len(data))
    return len(data)


@ffi.def_extern()
def daran_py_now_ms(ctx):
    return (time.monotonic_ns() // 1000000) & 0xFFFFFFFF


@ffi.def_extern()
def daran_py_on_line(ctx, line):
    ffi.from_handle(ctx)._lines.append(Line(line.kind, ffi.unpack(line.payload, line.len).decode()))


@ffi.def_extern()
def daran_py_on_stray(ctx, line):
    link = ffi.from_handle(ctx)
    text = ffi.unpack(line.payload, line.len).decode()
    link.strays.append(text)
    if line.kind == lib.DARAN_CLIENT_LINE_ERROR:
        link.late_errors.append((line.error, text))


@ffi.def_extern()
def daran_py_on_report(ctx, report):
    values = tuple(number_value(report.values + i) for i in range(report.count))
    ffi.from_handle(ctx).reports.append(Report(report.id, float(report.time_s), values))


class LineLink:
    """The C link over one transport. Not for several threads at once: a
    lock serialises requests."""

    def __init__(self, transport, *, checksum=False, timeout=0.05, confirm=0.02, retries=1,
                 quiet=0.005, reports=4096):
        self._transport = transport
        self.timeout = timeout
        self.confirm = confirm
        self._handle = ffi.new_handle(self)
        self._c_transport = ffi.new("daran_client_transport_t *", {
            "write": lib.daran_py_write, "read": lib.daran_py_read, "now_ms": lib.daran_py_now_ms,
            "ctx": self._handle})
        # a port with a descriptor is read and written by C: no call back into Python
        fd = getattr(transport, "fd", None)
        self._fd = ffi.new("int *", fd if fd is not None else -1)
        if fd is not None and not lib.daran_py_fd_transport(self._c_transport, self._fd):
            self._c_transport.write = lib.daran_py_write
            self._c_transport.read = lib.daran_py_read
            self._c_transport.now_ms = lib.daran_py_now_ms
            self._c_transport.ctx = self._handle
        config = ffi.new("daran_client_link_config_t *", {
            "checksum": checksum, "retries": retries, "quiet_ms": int(quiet * 1000),
            "on_report": lib.daran_py_on_report, "report_ctx": self._handle,
            "on_stray": lib.daran_py_on_stray, "stray_ctx": self._handle})
        self._c_link = ffi.new("daran_client_link_t *")
        result = lib.daran_client_link_init(self._c_link, self._c_transport, config)
        if result != Result.OK:
            raise LinkError(result, "daran_client_link_init")
        self._request = ffi.new("daran_client_request_t *")
        self._outcome = ffi.new("daran_client_outcome_t *")
        self._numbers = ffi.new("daran_client_number_t[]", lib.DARAN_CLIENT_REPORT_MAX)
        self._count = ffi.new("size_t *")
        self._parsed = ffi.new("daran_result_t *")
        self._last = ffi.new("daran_client_line_t *", {"kind": lib.DARAN_CLIENT_LINE_TEXT})
        self._lines = []
        self._callback_error = None
        self._lock = threading.RLock()
        #: telemetry reports not yet taken (oldest first; the oldest are dropped when full)
        self.reports = collections.deque(maxlen=reports)
        #: lines that answered no request (a late `error:` of an unconfirmed command)
        self.strays = collections.deque(maxlen=256)
        #: (result, line) of the `error:` lines among them: refusals that came after
        #: their command's `confirm` window
        self.late_errors = collections.deque(maxlen=256)
        self.closed = False
        self._state_batches = {}
        self._paths = {}
        self._checksum = checksum
        self._retries = retries
        self._build_buf = ffi.new("char[]", lib.DARAN_CLIENT_LINE_MAX)
        self._build_len = ffi.new("size_t *")
        self._reply = ffi.new("daran_client_line_t *")
        self._report = ffi.new("daran_client_report_t *")

    # -- requests ---------------------------------------------------------------------------

    def transact(self, command, drive_id, values=(), *, path=None, system=None, value=None,
                 ctype=None, timeout=None, collect=False):
        """Send one request (the protocol table's command name: "T", "R", "H_PROPERTIES")
        and wait for its reply. Returns the reply lines when `collect`, else None (a
        one-line reply stays in the C link for values()). Raises DriveRefused, NoReply,
        LinkError."""
        if self.closed:
            raise LinkError(Result.ERR_BUS_ERROR, "the link is closed")
        code = COMMANDS[command]
        if timeout is None:
            timeout = self.confirm if _SILENT[code] else self.timeout
        with self._lock:
            request = self._request
            request.command = code
            request.id = drive_id
            request.value_count = len(values)
            for i, v in enumerate(values):
                request.values[i] = v
            lib.daran_py_request_path(request, self._c_path(path), SCOPE[system])
            if value is not None:
                self._set_value(value, ctype)
            if collect:
                self._lines = []
            self._callback_error = None
            result = lib.daran_client_transact(
                self._c_link, request, int(timeout * 1000),
                lib.daran_py_on_line if collect else ffi.NULL, self._handle, self._outcome)
            if self._callback_error is not None:
                raise LinkError(Result.ERR_BUS_ERROR, f"transport: {self._callback_error}") \
                    from self._callback_error
            if result:
                raise_for(result, self._outcome.drive_error, _describe(command, drive_id, path))
            return self._lines if collect else None

    def _c_path(self, path):
        """A path as a C string, kept: a loop of requests builds each path once."""
        if path is None:
            return ffi.NULL
        c_path = self._paths.get(path)
        if c_path is None:
            if len(self._paths) > 1024:
                self._paths.clear()
            c_path = self._paths[path] = ffi.new("char[]", path.encode())
        return c_path

    def _set_value(self, value, ctype):
        if ctype is None:
            if isinstance(value, (bool, int)):
                ctype = lib.DARAN_CLIENT_TYPE_S32 if value < 0 else lib.DARAN_CLIENT_TYPE_U64
            else:
                ctype = lib.DARAN_CLIENT_TYPE_F32
        if ctype == lib.DARAN_CLIENT_TYPE_F32:
            lib.daran_py_request_value(self._request, lib.DARAN_CLIENT_VALUE_F32, float(value), 0, 0)
        elif ctype == lib.DARAN_CLIENT_TYPE_S32:
            lib.daran_py_request_value(self._request, lib.DARAN_CLIENT_VALUE_INT, 0, 0, _integer(value))
        else:
            v = _integer(value)
            if v < 0:
                raise ValueError(f"{value!r}: the property is unsigned")
            lib.daran_py_request_value(self._request, lib.DARAN_CLIENT_VALUE_UINT, 0, v, 0)

    def values(self, expected, types=None):
        """The numbers of the last one-line reply, each as its type (None: int or float)."""
        last = self._last
        last.kind = lib.DARAN_CLIENT_LINE_TEXT
        last.payload = self._c_link.last
        last.len = self._c_link.last_len
        result = lib.daran_client_parse_values(last, self._numbers, lib.DARAN_CLIENT_REPORT_MAX,
                                               expected, self._count)
        if result != Result.OK:
            raise LinkError(result, "reply: " + ffi.unpack(self._c_link.last,
                                                           self._c_link.last_len).decode())
        if types is None:
            return [number_value(self._numbers + i) for i in range(self._count[0])]
        return [number_value(self._numbers + i, t) for i, t in zip(range(self._count[0]), types)]

    def query_batch(self, queries, timeout=None):
        """Several one-line queries (`r f g i`) sent in one write, their replies read
        in order: one round trip instead of one each. `queries` holds (command, id,
        path, system, expected, types); returns one list of values per query. The
        lines are built, read and parsed by the C client (daran_client_build,
        daran_client_read_line, daran_client_parse_values); the batch is sent again,
        as the C link sends a query again, after a timeout or a damaged reply."""
        if self.closed:
            raise LinkError(Result.ERR_BUS_ERROR, "the link is closed")
        out = bytearray()
        request = self._request
        keep = []
        for command, drive_id, path, system, _, _ in queries:
            request.command = COMMANDS[command]
            if lib.daran_client_reply_shape(request.command) != lib.DARAN_CLIENT_REPLY_ONE_LINE:
                raise ValueError(f"{command}: only one-line queries are batched")
            request.id = drive_id
            request.value_count = 0
            keep.append(ffi.new("char[]", path.encode()) if path is not None else ffi.NULL)
            lib.daran_py_request_path(request, keep[-1], SCOPE[system])
            result = lib.daran_client_build(request, self._checksum, self._build_buf,
                                            lib.DARAN_CLIENT_LINE_MAX, self._build_len)
            if result != Result.OK:
                raise LinkError(result, _describe(command, drive_id, path))
            out += ffi.buffer(self._build_buf, self._build_len[0])
        timeout = self.timeout if timeout is None else timeout
        with self._lock:
            for attempt in range(self._retries + 1):
                lib.daran_client_link_service(self._c_link)  # what came before is no reply
                try:
                    return self._batch_once(bytes(out), queries, timeout)
                except (NoReply, LinkError) as exc:
                    if attempt == self._retries or isinstance(exc, DriveRefused):
                        raise
                    time.sleep(self._c_link.config.quiet_ms / 1000.0)
                    lib.daran_client_link_service(self._c_link)

    def _batch_once(self, data, queries, timeout):
        if not self._transport.write(data):
            raise LinkError(Result.ERR_BUS_ERROR, "the port could not write")
        answers = []
        refused = None
        pending = b""
        deadline = time.monotonic() + timeout
        while len(answers) < len(queries):
            left = deadline - time.monotonic()
            chunk = self._transport.read(4096, max(0, int(left * 1000))) if left > 0 else b""
            if not chunk:
                command, drive_id, path = queries[len(answers)][:3]
                raise NoReply(Result.ERR_NO_REPLY, _describe(command, drive_id, path))
            pending += chunk
            while b"\n" in pending and len(answers) < len(queries):
                text, _, pending = pending.partition(b"\n")
                result = lib.daran_client_read_line(text, len(text), self._checksum, self._reply)
                if result != Result.OK:
                    raise LinkError(result, f"reply {text!r}")
                if self._reply.kind == lib.DARAN_CLIENT_LINE_TELEMETRY:
                    if lib.daran_client_parse_report(self._reply, self._report) == Result.OK:
                        daran_py_on_report(self._handle, self._report)
                    continue
                command, drive_id, path, _, expected, types = queries[len(answers)]
                if self._reply.kind == lib.DARAN_CLIENT_LINE_ERROR:
                    refused = refused or DriveRefused(self._reply.error,
                                                      _describe(command, drive_id, path))
                    answers.append(None)
                    continue
                result = lib.daran_client_parse_values(self._reply, self._numbers,
                                                       lib.DARAN_CLIENT_REPORT_MAX, expected,
                                                       self._count)
                if result != Result.OK:
                    raise LinkError(result, f"reply {text!r}")
                count = self._count[0]
                answers.append([number_value(self._numbers + i, types[i] if types else None)
                                for i in range(count)])
        if pending.strip():
            self.strays.append(pending.decode(errors="replace"))
        if refused is not None:
            raise refused
        return answers

    def set_checksum(self, on):
        """Send (and expect) ` *N` checksums from now on."""
        self._checksum = bool(on)
        self._c_link.config.checksum = bool(on)

    # -- what a Drive asks of its link (daran.can.CanLink answers the same) ------------------

    def command(self, command, drive_id, values, wait=None):
        """A command answered with nothing (motion, preset, start, system)."""
        self.transact(command, drive_id, values, timeout=wait)

    def query(self, command, drive_id, expected, types):
        """`f g i`: the values of its one reply line."""
        with self._lock:
            self.transact(command, drive_id)
            return self.values(expected, types)

    def read(self, drive_id, path, prop):
        """`r`: the value of a property (prop: its Property, None when unknown)."""
        if self.closed:
            raise LinkError(Result.ERR_BUS_ERROR, "the link is closed")
        with self._lock:
            request = self._request
            request.command = _READ
            request.id = drive_id
            request.value_count = 0
            lib.daran_py_request_path(request, self._c_path(path),
                                      SCOPE[prop.system if prop else None])
            number = self._numbers
            result = lib.daran_py_query_one(self._c_link, request, int(self.timeout * 1000),
                                            self._outcome, number, self._parsed)
            if result:
                raise_for(result, self._outcome.drive_error, _describe("R", drive_id, path))
            if self._parsed[0]:
                raise LinkError(self._parsed[0], "reply: " + ffi.unpack(
                    self._c_link.last, self._c_link.last_len).decode())
            if prop is None:
                return number_value(number)
            if prop.ctype == lib.DARAN_CLIENT_TYPE_F32:
                return float(number[0].f32)
            return number_value(number, prop.ctype)

    def read_text(self, drive_id, prop):
        """`r` of a property: its value as the drive printed it."""
        self.transact("R", drive_id, path=prop.path, system=prop.system)
        return ffi.unpack(self._c_link.last, self._c_link.last_len).decode()

    def write(self, drive_id, path, prop, value, wait=None):
        """`w`, the value sent as the property's type."""
        self.transact("W", drive_id, path=path, system=prop.system if prop else None,
                      value=value, ctype=prop.ctype if prop else None, timeout=wait)

    def state(self, drive_id):
        """`f` and the reads of torque, trajectory_done and error in one write."""
        batch = self._state_batches.get(drive_id)
        if batch is None:
            batch = self._state_batches[drive_id] = [("F", drive_id, None, None, 2, _F2)] + [
                ("R", drive_id, path, False, 1, (PROPERTIES[path].ctype,)) for path in _STATE_READS]
        (position, velocity), (torque,), (done,), (error,) = self.query_batch(batch)
        return State(position, velocity, torque, done, error)

    def error_registers(self, drive_id):
        """`e`: the seven registers' values."""
        return self.parse_errors(self.transact("E", drive_id, collect=True))

    def discover(self, drive_id, prefix=None):
        """`h id properties [prefix]`: the drive's table, by path."""
        lines = self.transact("H_PROPERTIES", drive_id, path=prefix, collect=True)
        return {prop.path: prop for prop in map(self.parse_property, lines)}

    def parse_errors(self, lines):
        """`e`'s reply lines -> the seven register values (each line checked by the C client
        against its register's name and place)."""
        errors = ffi.new("daran_client_errors_t *")
        if len(lines) != lib.DARAN_CLIENT_ERROR_REGISTERS:
            raise LinkError(Result.ERR_INVALID_VALUE, f"e: {len(lines)} lines")
        for index, line in enumerate(lines):
            c_line, keep = _c_line(line)
            result = lib.daran_client_parse_error_line(c_line, index, errors)
            if result != Result.OK:
                raise LinkError(result, f"e: {line.text!r}")
        return [errors.reg[i] for i in range(lib.DARAN_CLIENT_ERROR_REGISTERS)]

    def parse_property(self, line):
        """A discovery line -> its Property (path without `axis0.`)."""
        c_line, keep = _c_line(line)
        prop = ffi.new("daran_client_property_t *")
        result = lib.daran_client_parse_property(c_line, prop)
        if result != Result.OK:
            raise LinkError(result, f"discovery: {line.text!r}")
        path = ffi.unpack(prop.path, prop.path_len).decode()
        system = not path.startswith("axis0.")
        if not system:
            path = path[len("axis0."):]
        known = PROPERTIES.get(path)
        return Property(path, system, prop.type, bool(prop.writable),
                        ffi.unpack(prop.unit, prop.unit_len).decode(),
                        ffi.unpack(prop.range, prop.range_len).decode(),
                        known.can if known else 0)

    def send_line(self, text, timeout=None):
        """Send a line written by hand (a console): sealed, sent once, never retried;
        returns its reply lines."""
        payload = text.encode()
        shape = lib.daran_client_line_shape(payload, len(payload), ffi.NULL)
        if timeout is None:
            timeout = self.confirm if shape == lib.DARAN_CLIENT_REPLY_SILENT else self.timeout
        with self._lock:
            self._lines = []
            self._callback_error = None
            result = lib.daran_client_transact_line(self._c_link, payload, len(payload), shape,
                                                    int(timeout * 1000), lib.daran_py_on_line,
                                                    self._handle, self._outcome)
            if self._callback_error is not None:
                raise LinkError(Result.ERR_BUS_ERROR, f"transport: {self._callback_error}")
            if result != Result.OK:
                raise_for(result, self._outcome.drive_error, text)
            return [line.text for line in self._lines]

    def service(self):
        """Read what the transport holds now: telemetry to .reports, other lines to .strays."""
        with self._lock:
            lib.daran_client_link_service(self._c_link)

    @property
    def bad_lines(self):
        """Received lines the C link dropped (damaged, too long, unreadable)."""
        return self._c_link.bad_lines

    def close(self):
        if not self.closed:
            self.closed = True
            self._transport.close()


_F2 = (lib.DARAN_CLIENT_TYPE_F32,) * 2
_READ = COMMANDS["R"]
#: by command code: whether it is answered with nothing (its wait is `confirm`)
_SILENT = [lib.daran_client_reply_shape(code) == lib.DARAN_CLIENT_REPLY_SILENT
           for code in range(lib.DARAN_CLIENT_CMD_COUNT)]
#: what state() reads beside `f`: the status frame's torque, T and E, by property
_STATE_READS = ("output_shaft.torque_estimate", "controller.trajectory_done", "error")


def _c_line(line):
    """A daran_client_line_t viewing a Line's text, and the buffer to keep alive."""
    keep = ffi.new("char[]", line.text.encode())
    c_line = ffi.new("daran_client_line_t *", {"kind": line.kind, "payload": keep,
                                                 "len": len(keep) - 1})
    return c_line, keep


def _integer(value):
    if isinstance(value, float):
        if not value.is_integer():
            raise ValueError(f"{value!r}: the property takes an integer")
        return int(value)
    return int(value)


def _describe(command, drive_id, path):
    word = ffi.string(lib.daran_client_command_word(COMMANDS[command])).decode()
    return f"{word} {path} (drive {drive_id})" if path else f"{word} {drive_id}"


def lookup(path, table=PROPERTIES):
    """The Property of a path written with or without `axisN.`; None when unknown."""
    if path.startswith("axis"):
        head, _, rest = path.partition(".")
        if head[4:].isdigit():
            return table.get(rest)
    return table.get(path)


__all__ = ["LineLink", "Report", "Line", "Property", "lookup", "number_value"]
