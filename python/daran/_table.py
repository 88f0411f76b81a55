"""The C client's tables as Python values: the protocol's commands, the
results and their phrases, the vendor's property table and error bit names.
Every value here is read from the extension, which compiled them from the
repository's X-lists (daran_protocol.h, daran_result.h, daran_properties.h,
cli/errors_bits.c); nothing is retyped."""
import enum
from typing import NamedTuple

from ._client import ffi, lib

#: command name (the protocol table's NAME: "T", "MS", "H_PROPERTIES") -> enum value
COMMANDS = {ffi.string(lib.daran_py_command_names[i]).decode(): i
            for i in range(lib.DARAN_CLIENT_CMD_COUNT)}

Result = enum.IntEnum("Result", [(ffi.string(lib.daran_py_result_names[i]).decode(), i)
                                 for i in range(lib.daran_py_result_count)])
Result.__doc__ = "daran_result_t: DARAN_OK, DARAN_ERR_*, without the DARAN_ prefix"


def phrase(result: int) -> str:
    """The protocol's phrase of a result ("value out of range")."""
    return ffi.string(lib.daran_result_phrase(result)).decode()


#: the C type code -> the Python type a value of it reads as
TYPES = {lib.DARAN_CLIENT_TYPE_F32: float, lib.DARAN_CLIENT_TYPE_U32: int,
         lib.DARAN_CLIENT_TYPE_S32: int, lib.DARAN_CLIENT_TYPE_U64: int,
         lib.DARAN_CLIENT_TYPE_BOOL: bool}
TYPE_NAMES = {lib.DARAN_CLIENT_TYPE_F32: "f32", lib.DARAN_CLIENT_TYPE_U32: "u32",
              lib.DARAN_CLIENT_TYPE_S32: "s32", lib.DARAN_CLIENT_TYPE_U64: "u64",
              lib.DARAN_CLIENT_TYPE_BOOL: "bool"}


class Property(NamedTuple):
    """One property: `path` as written without `axisN.`; `system` when the id
    goes last on the line (else it is an axis property)."""
    path: str
    system: bool
    ctype: int
    writable: bool
    unit: str
    range: str
    can: int  # its vendor CAN address, 0 when none
    name: str = ""  # its id in the C table (DARAN_PROP_<name>), "" when discovered

    @property
    def type(self) -> type:
        return TYPES[self.ctype]

    @property
    def type_name(self) -> str:
        return TYPE_NAMES[self.ctype]


def _builtin_properties():
    rows = {}
    for i in range(lib.daran_py_property_count):
        row = lib.daran_py_properties[i]
        prop = Property(ffi.string(row.path).decode(), bool(row.system), row.type,
                        bool(row.writable), ffi.string(row.unit).decode(),
                        ffi.string(row.range).decode(), row.can, ffi.string(row.name).decode())
        rows[prop.path] = prop
    return rows


#: the vendor's table (and the library's extensions), by path
PROPERTIES = _builtin_properties()

#: the same rows by their id name (POS_ESTIMATE)
BY_NAME = {prop.name: prop for prop in PROPERTIES.values()}


def query_properties(command):
    """The Property rows a query (`F`, `G`, `I`, `E`) reads, in its reply's order."""
    names = getattr(lib, "daran_py_query_" + command.lower())
    rows, i = [], 0
    while names[i] != ffi.NULL:
        rows.append(BY_NAME[ffi.string(names[i]).decode()])
        i += 1
    return rows


ERROR_REGISTERS = [ffi.string(lib.daran_client_error_register_name(i)).decode()
                   for i in range(lib.DARAN_CLIENT_ERROR_REGISTERS)]


def error_bit_name(register: int, bit: int) -> str:
    """The vendor's name of a bit of `e`'s register (`ESTOP_REQUESTED`), or `bit N`."""
    name = lib.cli_error_bit_name(register, bit)
    return ffi.string(name).decode() if name != ffi.NULL else f"bit {bit}"
