"""The cffi builder of daran._client (API mode): the C client of this
repository compiled into the extension, so that every request is built,
every reply parsed, every number converted and every checksum made by the
same C code the drive and the `daran` tool use.

API mode (not ABI mode): the compiler checks the declarations below against
the real headers, the enums take their values from them, and there is no
shared library to find at run time. The sources are the client's and the
few core files it calls (numbers, checksum, phrases), the core's CAN codec
(the vendor's frames: layouts, exact s16x100 scaling, modes), the CLI's table
of the vendor's error bit names and its dump file reader; they are read from the repository this
folder sits in (python/..), so the package is built from a checkout.
"""
import os
import pathlib

from cffi import FFI

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
if not (ROOT / "include" / "daran_client.h").exists():
    raise SystemExit(f"daran_build: {ROOT}/include/daran_client.h is missing: build the package "
                     "from its place in a daran-ascii checkout (python/)")

SOURCES = [
    "client/request.c", "client/reply.c", "client/link.c",
    "src/text/number.c", "src/text/text.c", "src/text/result.c", "src/link/checksum.c",
    "cli/errors_bits.c",
    "src/can/can_codec.c", "src/can/can_encode.c",
    "cli/dump_file.c", "cli/args.c", "cli/fail.c",
]
INCLUDE_DIRS = ["include", "src", "src/text", "src/link", "src/can", "src/request", "cli"]

ffibuilder = FFI()

ffibuilder.cdef(r"""
#define DARAN_CLIENT_LINE_MAX ...
#define DARAN_CLIENT_VALUES_MAX ...
#define DARAN_CLIENT_REPORT_MAX ...
#define DARAN_CLIENT_ERROR_REGISTERS ...
#define DARAN_CLIENT_ID_MAX ...

typedef int... daran_result_t;
typedef enum daran_client_command { DARAN_CLIENT_CMD_COUNT, ... } daran_client_command_t;
typedef enum daran_client_reply_shape { DARAN_CLIENT_REPLY_SILENT, DARAN_CLIENT_REPLY_ONE_LINE,
    DARAN_CLIENT_REPLY_ERROR_LINES, DARAN_CLIENT_REPLY_UNTIL_END, DARAN_CLIENT_REPLY_UNTIL_QUIET
} daran_client_reply_shape_t;
typedef enum daran_client_class { DARAN_CLIENT_CLASS_MOTION, DARAN_CLIENT_CLASS_PRESET,
    DARAN_CLIENT_CLASS_WRITE, DARAN_CLIENT_CLASS_SYSTEM, DARAN_CLIENT_CLASS_QUERY
} daran_client_class_t;
typedef enum daran_client_scope { DARAN_CLIENT_SCOPE_AUTO, DARAN_CLIENT_SCOPE_AXIS,
    DARAN_CLIENT_SCOPE_SYSTEM } daran_client_scope_t;
typedef enum daran_client_value_kind { DARAN_CLIENT_VALUE_F32, DARAN_CLIENT_VALUE_UINT,
    DARAN_CLIENT_VALUE_INT } daran_client_value_kind_t;
typedef struct daran_client_value { daran_client_value_kind_t kind; float f32; uint64_t uint;
    int64_t sint; } daran_client_value_t;
typedef struct daran_client_request {
    daran_client_command_t command; uint8_t id; uint8_t value_count;
    float values[];  /* DARAN_CLIENT_VALUES_MAX */
    ...;
} daran_client_request_t;
typedef enum daran_client_line_kind { DARAN_CLIENT_LINE_TEXT, DARAN_CLIENT_LINE_ERROR,
    DARAN_CLIENT_LINE_END, DARAN_CLIENT_LINE_TELEMETRY } daran_client_line_kind_t;
typedef struct daran_client_line { daran_client_line_kind_t kind; const char *payload; size_t len;
    bool had_checksum; daran_result_t error; } daran_client_line_t;
typedef struct daran_client_number { float f32; uint64_t magnitude; bool negative;
    bool is_integer; } daran_client_number_t;
typedef struct daran_client_errors { uint32_t reg[]; ...; } daran_client_errors_t;
typedef struct daran_client_report { uint8_t id; float time_s; size_t count;
    daran_client_number_t values[]; ...; } daran_client_report_t;
typedef enum daran_client_type { DARAN_CLIENT_TYPE_F32, DARAN_CLIENT_TYPE_U32,
    DARAN_CLIENT_TYPE_S32, DARAN_CLIENT_TYPE_U64, DARAN_CLIENT_TYPE_BOOL } daran_client_type_t;
typedef struct daran_client_property { const char *path; size_t path_len; daran_client_type_t type;
    bool writable; const char *unit; size_t unit_len; const char *range; size_t range_len;
} daran_client_property_t;
typedef struct daran_client_transport {
    bool (*write)(void *ctx, const char *bytes, size_t len);
    size_t (*read)(void *ctx, char *buf, size_t size, uint32_t timeout_ms);
    uint32_t (*now_ms)(void *ctx);
    void *ctx;
} daran_client_transport_t;
typedef void (*daran_client_line_fn)(void *ctx, const daran_client_line_t *line);
typedef void (*daran_client_report_fn)(void *ctx, const daran_client_report_t *report);
typedef struct daran_client_link_config {
    bool checksum; uint8_t retries; uint32_t quiet_ms;
    daran_client_report_fn on_report; void *report_ctx;
    daran_client_line_fn on_stray; void *stray_ctx;
} daran_client_link_config_t;
typedef struct daran_client_outcome { bool drive_error; uint8_t attempts; size_t lines;
} daran_client_outcome_t;
typedef struct daran_client_link { daran_client_link_config_t config; char last[]; size_t last_len;
    uint32_t bad_lines; ...;
} daran_client_link_t;

const char *daran_client_command_word(daran_client_command_t command);
daran_client_reply_shape_t daran_client_reply_shape(daran_client_command_t command);
daran_client_class_t daran_client_command_class(daran_client_command_t command);
bool daran_client_may_retry(daran_client_command_t command);
daran_result_t daran_client_build(const daran_client_request_t *request, bool with_checksum,
                                  char *buf, size_t size, size_t *len);
daran_result_t daran_client_seal(char *buf, size_t size, size_t payload_len, bool with_checksum,
                                 size_t *len);
daran_client_scope_t daran_client_path_scope(const char *path, size_t len);
daran_result_t daran_client_read_line(const char *text, size_t len, bool checksum_expected,
                                      daran_client_line_t *out);
daran_result_t daran_client_parse_number(const char *text, size_t len, daran_client_number_t *out);
daran_result_t daran_client_number_u32(const daran_client_number_t *n, uint32_t *out);
daran_result_t daran_client_number_s32(const daran_client_number_t *n, int32_t *out);
daran_result_t daran_client_number_u64(const daran_client_number_t *n, uint64_t *out);
daran_result_t daran_client_parse_values(const daran_client_line_t *line, daran_client_number_t *out,
                                         size_t max, size_t expected, size_t *count);
const char *daran_client_error_register_name(size_t index);
daran_result_t daran_client_parse_error_line(const daran_client_line_t *line, size_t index,
                                             daran_client_errors_t *errors);
daran_result_t daran_client_parse_report(const daran_client_line_t *line, daran_client_report_t *out);
daran_result_t daran_client_parse_property(const daran_client_line_t *line,
                                           daran_client_property_t *out);
daran_result_t daran_client_link_init(daran_client_link_t *link,
                                      const daran_client_transport_t *transport,
                                      const daran_client_link_config_t *config);
daran_result_t daran_client_transact(daran_client_link_t *link, const daran_client_request_t *request,
                                     uint32_t timeout_ms, daran_client_line_fn on_line,
                                     void *line_ctx, daran_client_outcome_t *outcome);
daran_result_t daran_client_transact_line(daran_client_link_t *link, const char *payload,
                                          size_t payload_len, daran_client_reply_shape_t shape,
                                          uint32_t timeout_ms, daran_client_line_fn on_line,
                                          void *line_ctx, daran_client_outcome_t *outcome);
daran_client_reply_shape_t daran_client_line_shape(const char *payload, size_t len, bool *known);
void daran_client_link_service(daran_client_link_t *link);
const char *daran_result_phrase(daran_result_t result);
const char *cli_error_bit_name(size_t reg, unsigned bit);

/* glue (below): the request's path, scope and value, which cffi cannot
   place by name in a struct declared with `...` */
void daran_py_request_path(daran_client_request_t *request, const char *path, int scope);
void daran_py_request_value(daran_client_request_t *request, daran_client_value_kind_t kind,
                            double f, uint64_t u, int64_t s);

/* the vendor's property table, from DARAN_PROPERTY_LIST */
typedef struct daran_py_property {
    const char *name; const char *path; int system; daran_client_type_t type; int writable;
    const char *range; const char *unit; unsigned can;
} daran_py_property_t;
extern const daran_py_property_t daran_py_properties[];
extern const size_t daran_py_property_count;

/* the commands of the protocol table, from DARAN_PROTOCOL_COMMANDS, and the
   results, from DARAN_RESULT_LIST: names by enum value */
extern const char *const daran_py_command_names[];
extern const char *const daran_py_result_names[];
extern const size_t daran_py_result_count;

/* the properties each query reads (daran_protocol.h's DARAN_QUERY_*), by id
   name, ended by NULL: what `f g i e` are on CAN */
extern const char *const daran_py_query_f[];
extern const char *const daran_py_query_g[];
extern const char *const daran_py_query_i[];
extern const char *const daran_py_query_e[];

/* the CAN codec (src/can/can_codec.h): codes, layouts, exact scaling */
#define DARAN_CAN_SYSTEM ...
#define DARAN_CAN_PRESET ...
#define DARAN_CAN_TRACK ...
#define DARAN_CAN_READ ...
#define DARAN_CAN_WRITE ...
#define DARAN_CAN_STATUS ...
#define DARAN_CAN_SUB_SAVE ...
#define DARAN_CAN_SUB_START_TRACK ...
#define DARAN_CAN_SUB_START_IMPEDANCE ...
#define DARAN_CAN_SUB_FEED ...
#define DARAN_CAN_TYPE_F32 ...
#define DARAN_CAN_TYPE_U16 ...
#define DARAN_CAN_TYPE_S16 ...
#define DARAN_CAN_TYPE_U32 ...
#define DARAN_CAN_TYPE_S32 ...
typedef enum daran_can_layout { DARAN_CAN_LAYOUT_TRACK, DARAN_CAN_LAYOUT_TRAPEZOID,
    DARAN_CAN_LAYOUT_PASSTHROUGH, DARAN_CAN_LAYOUT_VELOCITY, DARAN_CAN_LAYOUT_TORQUE,
    DARAN_CAN_LAYOUT_PRESET, DARAN_CAN_LAYOUT_GAINS } daran_can_layout_t;
bool daran_can_encode_values(daran_can_layout_t layout, const float *values, uint8_t *data);
void daran_can_decode_values(daran_can_layout_t layout, const uint8_t *data, float *values);
uint16_t daran_can_get_u16(const uint8_t *bytes);
uint32_t daran_can_get_u32(const uint8_t *bytes);
float daran_can_get_f32(const uint8_t *bytes);
float daran_can_get_scaled(const uint8_t *bytes);
void daran_can_put_u16(uint8_t *bytes, uint32_t value);
void daran_can_put_u32(uint8_t *bytes, uint32_t value);
void daran_can_put_f32(uint8_t *bytes, float value);
void daran_can_put_property(uint8_t *data, uint32_t address, uint32_t type, uint32_t bits);

/* the CLI's dump file (cli/dump_file.h): which properties are configuration, and
   its reader (messages on stderr, as the CLI's) */
typedef int... cli_status_t;
typedef struct dump_entry { char path[]; bool axis; char value[]; daran_client_value_t parsed;
    unsigned line; ...; } dump_entry_t;
typedef struct dump_file { dump_entry_t entries[]; size_t count; char firmware[]; ...;
} dump_file_t;
cli_status_t dump_file_read(const char *name, uint8_t id, dump_file_t *out);
const char *dump_not_restored_why(const char *path, const char *range);
size_t daran_format_float(float value, char *buf, size_t size);

/* a one-value query in one call: daran_client_transact (its result returned), then
   daran_client_parse_values of its reply line, exactly one number (*parsed) */
daran_result_t daran_py_query_one(daran_client_link_t *link, const daran_client_request_t *request,
                                  uint32_t timeout_ms, daran_client_outcome_t *outcome,
                                  daran_client_number_t *number, daran_result_t *parsed);

/* a transport over a POSIX file descriptor (a serial port, a pty), in C: a request
   then runs without a call back into Python (docs/python.md, "Figures") */
bool daran_py_fd_transport(daran_client_transport_t *transport, int *fd);

/* the link's transport, in Python */
extern "Python" bool daran_py_write(void *ctx, const char *bytes, size_t len);
extern "Python" size_t daran_py_read(void *ctx, char *buf, size_t size, uint32_t timeout_ms);
extern "Python" uint32_t daran_py_now_ms(void *ctx);
extern "Python" void daran_py_on_line(void *ctx, const daran_client_line_t *line);
extern "Python" void daran_py_on_report(void *ctx, const daran_client_report_t *report);
extern "Python" void daran_py_on_stray(void *ctx, const daran_client_line_t *line);
""")

ffibuilder.set_source("daran._client", r"""
#include "daran_client.h"
#include "daran_properties.h"
#include "errors_bits.h"
#include "can_codec.h"
#include "dump_file.h"
#include "number.h"

#if defined(__unix__) || defined(__APPLE__)
#include <errno.h>
#include <poll.h>
#include <time.h>
#include <unistd.h>

static bool fd_write(void *ctx, const char *bytes, size_t len)
{
    int fd = *(const int *)ctx;
    while (len > 0) {
        ssize_t n = write(fd, bytes, len);
        if (n > 0) {
            bytes += n;
            len -= (size_t)n;
            continue;
        }
        struct pollfd p = {fd, POLLOUT, 0};
        if (n < 0 && (errno == EAGAIN || errno == EINTR) && poll(&p, 1, 1000) >= 0) {
            continue;
        }
        return false;
    }
    return true;
}

static size_t fd_read(void *ctx, char *buf, size_t size, uint32_t timeout_ms)
{
    int fd = *(const int *)ctx;
    struct pollfd p = {fd, POLLIN, 0};
    if (poll(&p, 1, (int)timeout_ms) <= 0) {
        return 0;
    }
    ssize_t n = read(fd, buf, size);
    return n > 0 ? (size_t)n : 0;
}

static uint32_t fd_now_ms(void *ctx)
{
    (void)ctx;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (uint32_t)((uint64_t)t.tv_sec * 1000u + (uint64_t)t.tv_nsec / 1000000u);
}

bool daran_py_fd_transport(daran_client_transport_t *transport, int *fd)
{
    transport->write = fd_write;
    transport->read = fd_read;
    transport->now_ms = fd_now_ms;
    transport->ctx = fd;
    return true;
}
#else
bool daran_py_fd_transport(daran_client_transport_t *transport, int *fd)
{
    (void)transport;
    (void)fd;
    return false;
}
#endif

daran_result_t daran_py_query_one(daran_client_link_t *link, const daran_client_request_t *request,
                                  uint32_t timeout_ms, daran_client_outcome_t *outcome,
                                  daran_client_number_t *number, daran_result_t *parsed)
{
    daran_result_t result = daran_client_transact(link, request, timeout_ms, NULL, NULL, outcome);
    *parsed = DARAN_OK;
    if (result == DARAN_OK) {
        daran_client_line_t line = {DARAN_CLIENT_LINE_TEXT, link->last, link->last_len, false,
                                    DARAN_OK};
        size_t count;
        *parsed = daran_client_parse_values(&line, number, 1, 1, &count);
    }
    return result;
}

void daran_py_request_path(daran_client_request_t *request, const char *path, int scope)
{
    request->path = path;
    request->scope = (daran_client_scope_t)scope;
}

void daran_py_request_value(daran_client_request_t *request, daran_client_value_kind_t kind,
                            double f, uint64_t u, int64_t s)
{
    request->value.kind = kind;
    request->value.f32 = (float)f;
    request->value.uint = u;
    request->value.sint = s;
}

typedef struct daran_py_property {
    const char *name; const char *path; int system; daran_client_type_t type; int writable;
    const char *range; const char *unit; unsigned can;
} daran_py_property_t;

#define DARAN_PY_SYSTEM_AXIS 0
#define DARAN_PY_SYSTEM_SYSTEM 1
#define DARAN_PY_WRITABLE_RO 0
#define DARAN_PY_WRITABLE_RW 1
#define DARAN_PY_ROW_(id, path, scope, type, access, range, unit, can) \
    {#id, path, DARAN_PY_SYSTEM_##scope, DARAN_CLIENT_TYPE_##type, DARAN_PY_WRITABLE_##access, \
     #range, unit, can},
const daran_py_property_t daran_py_properties[] = {DARAN_PROPERTY_LIST(DARAN_PY_ROW_)};
const size_t daran_py_property_count = sizeof daran_py_properties / sizeof daran_py_properties[0];

#define DARAN_PY_COMMAND_(name, c0, c1, feature, cls, reply, retry, handler, arg, can, help, \
                          f1, f2, f3, f4, f5, f6) #name,
const char *const daran_py_command_names[] = {DARAN_PROTOCOL_COMMANDS(DARAN_PY_COMMAND_)};

#define DARAN_PY_NAME_(id) #id,
const char *const daran_py_query_f[] = {DARAN_QUERY_F(DARAN_PY_NAME_) NULL};
const char *const daran_py_query_g[] = {DARAN_QUERY_G(DARAN_PY_NAME_) NULL};
const char *const daran_py_query_i[] = {DARAN_QUERY_I(DARAN_PY_NAME_) NULL};
const char *const daran_py_query_e[] = {DARAN_QUERY_E(DARAN_PY_NAME_) NULL};

#define DARAN_PY_RESULT_(name, phrase) #name,
const char *const daran_py_result_names[] = {DARAN_RESULT_LIST(DARAN_PY_RESULT_)};
const size_t daran_py_result_count = DARAN_RESULT_COUNT;
""",
    # relative: setuptools refuses absolute source paths (it runs in python/)
    sources=[os.path.relpath(ROOT / s, HERE) for s in SOURCES],
    include_dirs=[str(ROOT / d) for d in INCLUDE_DIRS],
    extra_compile_args=["-std=c11", "-D_DEFAULT_SOURCE", "-O2", "-fno-math-errno"],
)

if __name__ == "__main__":
    ffibuilder.compile(verbose=True)
