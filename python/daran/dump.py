"""A drive's configuration to and from the CLI's dump file (docs/cli.md,
"dump, restore"): the file `daran dump` writes and `daran restore` reads,
with the same rule of what is configuration (the CLI's C code decides it,
compiled into the extension) and the same reader."""
import datetime
import os
import struct
import tempfile

from . import __version__
from ._client import ffi, lib
from ._table import Result
from .errors import DaranError, DriveRefused


def not_restored_why(prop):
    """Why a writable property is not configuration, or None (cli/dump_file.c)."""
    why = lib.dump_not_restored_why(prop.path.encode(), prop.range.encode() if "." in prop.range
                                    or prop.range[:1].isdigit() else b"")
    return None if why == ffi.NULL else ffi.string(why).decode()


def _w_line(drive, prop, text):
    return (f"w {prop.path} {text} {drive.id}" if prop.system
            else f"w axis{drive.id}.{prop.path} {text}")


def dump(drive, source):
    """The dump of `drive` as text; `source` names where its table came from."""
    firmware, hardware, serial = drive.info()
    lines, restorable = [], 0
    for prop in sorted(drive._table.values(), key=lambda p: (p.system, p.path)):
        if not prop.writable:
            continue
        try:
            text = drive.link.read_text(drive.id, prop)
        except DaranError as exc:
            lines.append(f"# not read: {prop.path} ({exc.phrase})")
            continue
        if prop.path == "config.can_node_id":
            continue  # the header's `# node id`
        why = not_restored_why(prop)
        if why:
            lines.append(f"# {_w_line(drive, prop, text)}  (not restored: {why})")
        else:
            lines.append(_w_line(drive, prop, text))
            restorable += 1
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    head = [f"# daran-python {__version__}: dump of drive {drive.id}",
            f"# firmware {firmware}, hardware {hardware}, serial number {serial}",
            f"# date {date}",
            f"# node id {drive.id} (not restored)",
            f"# {restorable} properties to restore, from {source}; "
            "restore with: daran restore ID FILE"]
    return "\n".join(head + lines) + "\n"


def read_file(path, drive_id):
    """The C reader of a dump file, each path as it goes to `drive_id`: a cdata
    dump_file_t. A file that is not a dump raises ValueError with the reader's message."""
    out = ffi.new("dump_file_t *")
    with tempfile.TemporaryFile() as captured:
        saved = os.dup(2)
        try:
            os.dup2(captured.fileno(), 2)
            status = lib.dump_file_read(os.fsencode(path), drive_id, out)
        finally:
            os.dup2(saved, 2)
            os.close(saved)
        captured.seek(0)
        message = captured.read().decode(errors="replace").strip()
    if status != 0:
        raise ValueError(message.removeprefix("daran: ") or f"{path}: not a dump file")
    return out


def _value(entry):
    parsed = entry.parsed
    if parsed.kind == lib.DARAN_CLIENT_VALUE_F32:
        return float(parsed.f32)
    if parsed.kind == lib.DARAN_CLIENT_VALUE_INT:
        return int(parsed.sint)
    return int(parsed.uint)


def _same(a, b):
    if isinstance(a, float) or isinstance(b, float):
        return struct.pack("f", float(a)) == struct.pack("f", float(b))
    return int(a) == int(b)


def restore(drive, path, save=False, force=False):
    """Write a dump file's configuration into `drive` (docs/python.md): the firmware
    checked (unless force), each line written and read back; at the first failure
    the values written so far are written back and the error is raised. Returns the
    lines whose value the drive keeps otherwise after the last write, as
    (line number, path, the file's value, the kept value)."""
    content = read_file(path, drive.id)
    firmware = ffi.string(content.firmware).decode()
    if not firmware and not force:
        raise ValueError(f"{path}: no `# firmware` line: not a dump (force=True restores it anyway)")
    if firmware and not force and firmware != str(drive.info()[0]):
        raise ValueError(f"{path} was dumped from firmware {firmware}; drive {drive.id} runs "
                         f"firmware {drive.info()[0]} (force=True restores it anyway)")
    entries = [content.entries[i] for i in range(content.count)]
    paths = [ffi.string(e.path).decode() for e in entries]
    previous = [drive.get(p) for p in paths]
    late = getattr(drive.link, "late_errors", None)
    written = 0
    try:
        for entry, p in zip(entries, paths):
            written += 1
            if late is not None:
                late.clear()
            drive.set(p, _value(entry))
            kept = drive.get(p)
            if late and not _same(kept, _value(entry)):
                # the refusal came after the write's confirm window, before its read-back
                raise DriveRefused(late[-1][0], f"w {p} {ffi.string(entry.value).decode()}")
    except DaranError:
        for p, value in list(zip(paths, previous))[:written][::-1]:
            drive.set(p, value)
        raise
    kept = []
    for entry, p in zip(entries, paths):
        value = drive.get(p)
        if not _same(value, _value(entry)):
            kept.append((entry.line, p, ffi.string(entry.value).decode(), value))
    if save:
        drive.save()
    return kept


def format_value(prop, value):
    """A value as the drive prints it: floats shortest round-trip (the core's printer)."""
    if prop.type is float:
        buf = ffi.new("char[32]")
        return ffi.unpack(buf, lib.daran_format_float(value, buf, 32)).decode()
    return str(int(value))


__all__ = ["dump", "restore", "read_file", "not_restored_why", "format_value", "Result"]
