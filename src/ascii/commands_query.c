/* Queries f g i e (and `r`'s reply): each answers with values read from the
 * HAL. `h` lives with the command table, whose text it prints. */
#include "compiler.h"
#include "handlers.h"
#include "hal.h"
#include "property.h"
#include "reply.h"

void daran_append_values(daran_drive_t *drive, const daran_value_t *values,
                                             const uint8_t *types, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        if (drive->reply_len > 0u) {
            daran_reply_space(drive);
        }
        switch ((daran_prop_type_t)types[i]) {
        case DARAN_TYPE_F32:
            daran_reply_f32(drive, values[i].f32);
            break;
        case DARAN_TYPE_U64:
            daran_reply_u64(drive, values[i].u64);
            break;
        case DARAN_TYPE_S32:
            if (values[i].s32 < 0) {
                daran_reply_text(drive, "-", 1);
            }
            /* the magnitude of INT32_MIN is 2^31: negate in 64 bits */
            daran_reply_u64(drive, (uint64_t)(values[i].s32 < 0 ? -(int64_t)values[i].s32
                                                                 : (int64_t)values[i].s32));
            break;
        default:
            daran_reply_u64(drive, values[i].u32);
            break;
        }
    }
}

daran_result_t daran_append_properties(daran_drive_t *drive, const daran_prop_t *props,
                                       size_t count)
{
    daran_value_t values[DARAN_APPEND_MAX];
    uint8_t types[DARAN_APPEND_MAX];
    for (size_t i = 0; i < count; i++) {
        daran_result_t result = daran_get(drive, props[i], &values[i]);
        if (result != DARAN_OK) {
            return result;
        }
        types[i] = (uint8_t)DARAN_PROPERTY_TYPE(daran_property_row(props[i]));
    }
    daran_append_values(drive, values, types, count);
    return DARAN_OK;
}

daran_result_t daran_reply_properties(daran_drive_t *drive, const daran_prop_t *props,
                                      size_t count)
{
    daran_reply_begin(drive);
    daran_result_t result = daran_append_properties(drive, props, count);
    if (result == DARAN_OK) {
        daran_reply_end(drive);
    }
    return result;
}

#define QUERY_PROP(name) DARAN_PROP_##name,
const daran_prop_t daran_query_props[] = {DARAN_QUERY_F(QUERY_PROP) DARAN_QUERY_G(QUERY_PROP)
                                              DARAN_QUERY_I(QUERY_PROP) DARAN_QUERY_E(QUERY_PROP)};
#undef QUERY_PROP
DARAN_STATIC_ASSERT(DARAN_QUERY_END_E - DARAN_QUERY_END_I == DARAN_ERROR_REGISTERS,
                    e_has_seven_lines);
DARAN_STATIC_ASSERT(DARAN_QUERY_END_I - DARAN_QUERY_END_F <= DARAN_APPEND_MAX, a_query_line_fits);
DARAN_STATIC_ASSERT(DARAN_QUERY_END_E < 32 && DARAN_ERROR_REGISTERS < 8, a_query_arg_fits_a_byte);

daran_result_t daran_cmd_query(daran_drive_t *drive, const daran_request_t *request)
{
    uint8_t count;
    const daran_prop_t *props = daran_query_of(request->command, &count);
    return daran_reply_properties(drive, props, count);
}

/* The error registers `e` answers, in the order and with the names the
 * vendor's error decoder expects: "name: value", one line each. */
#define error_registers (daran_query_props + DARAN_QUERY_END_I)
#define ERROR_REGISTER_COUNT DARAN_ERROR_REGISTERS

/* The bit of axis0.error that summarises each register after the first
 * (daran_hal.h): DARAN_FLAG_MOTOR_FAILED, _ENCODER_FAILED,
 * _CONTROLLER_FAILED, _OVERTEMP for both thermistors; 31 for can.error,
 * which no bit summarises. Bit numbers, not the masks: a byte each. */
static const uint8_t summary_bit[ERROR_REGISTER_COUNT - 1u] = {6, 8, 9, 18, 18, 31};

/* Each line's name and separator, in register order: the register's path
 * without ".error", `axis` for axis0.error itself. Stored as text with its
 * length, so `e` copies seven names instead of rebuilding seven paths from
 * the table; test_e_names_each_register_by_its_path holds them to the
 * table's paths. */
#define REGISTER_LINES(X)                                                                       \
    X(DARAN_AXIS_WORD ": ") X("motor: ") X("encoder: ") X("controller: ") X("fet_thermistor: ") \
    X("motor_thermistor: ") X("can: ")
#define NAME_TEXT(name) name "\0"
static const char register_names[] = REGISTER_LINES(NAME_TEXT);
#undef NAME_TEXT
#define NAME_LEN(name) (uint8_t)(sizeof name - 1u),
static const uint8_t register_name_len[] = {REGISTER_LINES(NAME_LEN)};
#undef NAME_LEN
DARAN_STATIC_ASSERT(sizeof register_name_len == ERROR_REGISTER_COUNT, a_name_for_each_register);

void daran_reply_error_registers(daran_drive_t *drive, const uint32_t *values)
{
    const char *name = register_names;
    for (size_t i = 0; i < ERROR_REGISTER_COUNT; i++) {
        daran_reply_begin(drive);
        daran_reply_text(drive, name, register_name_len[i]);
        daran_reply_u64(drive, values[i]);
        daran_reply_end(drive);
        name += register_name_len[i] + 1u;
    }
}

daran_result_t daran_cmd_errors(daran_drive_t *drive, const daran_request_t *request)
{
    /* Every register is read before the first line goes out: a failing read
     * answers one error line, never half a report (D24). axis0.error must
     * read. Another register whose read fails (a port without that
     * hardware answers `motor fault` or `invalid property` for it) reads 0
     * when axis0.error vouches for it, its summary bit clear; with the bit
     * set the report would hide a fault, so the read's error answers. A
     * port cannot leave these rows out of the table (the generator
     * refuses): their paths name the lines. */
    uint32_t values[ERROR_REGISTER_COUNT];
    (void)request;
    for (size_t i = 0; i < ERROR_REGISTER_COUNT; i++) {
        daran_value_t value;
        daran_result_t result = daran_get(drive, error_registers[i], &value);
        if (result != DARAN_OK && (i == 0u || (values[0] >> summary_bit[i - 1u] & 1u) != 0u)) {
            return result;
        }
        values[i] = result == DARAN_OK ? value.u32 : 0u;
    }
    daran_reply_error_registers(drive, values);
    return DARAN_OK;
}
