/* Telemetry reports (protocol.md 11.2): `@<id> <t> <values> *N`, one line
 * every `axis0.telemetry.period` seconds (whole control ticks, at least
 * one), with the values `axis0.telemetry.fields` selects, in bit order. The
 * port calls daran_telemetry_tick() once per control tick from the context
 * that runs daran_poll(), so a report never falls inside a reply. A build
 * with DARAN_ENABLE_TELEMETRY 0 keeps a tick that does nothing. */
#include "compiler.h"
#include "hal.h"
#include "handlers.h"
#include "number.h"
#include "reply.h"
#include "telemetry.h"

#include "daran_port.h"

#if DARAN_ENABLE_TELEMETRY

/* The widest text of each kind of value, with the space before it: a float,
 * the error register (a u32, 10 digits), the trajectory flag (one digit). */
#define F32_WIDTH (1u + DARAN_F32_TEXT_MAX)
#define U32_WIDTH (1u + 10u)
#define FLAG_WIDTH (1u + 1u)

/* What each field bit reports, in bit order, and its widest text. */
#define TELEMETRY_FIELDS(X)                                                               \
    X(DARAN_PROP_POS_ESTIMATE, F32_WIDTH) X(DARAN_PROP_VEL_ESTIMATE, F32_WIDTH)           \
    X(DARAN_PROP_TORQUE_ESTIMATE, F32_WIDTH) X(DARAN_PROP_IQ_MEASURED, F32_WIDTH)         \
    X(DARAN_PROP_VBUS_VOLTAGE, F32_WIDTH) X(DARAN_PROP_FET_TEMPERATURE, F32_WIDTH)        \
    X(DARAN_PROP_MOTOR_TEMPERATURE, F32_WIDTH) X(DARAN_PROP_AXIS_ERROR, U32_WIDTH)        \
    X(DARAN_PROP_TRAJECTORY_DONE, FLAG_WIDTH)

#define PROP_OF(prop, width) prop,
static const uint8_t field_props[] = {TELEMETRY_FIELDS(PROP_OF)};
#undef PROP_OF
#define WIDTH_OF(prop, width) width,
static const uint8_t field_width[] = {TELEMETRY_FIELDS(WIDTH_OF)};
#undef WIDTH_OF
#define PLUS_WIDTH(prop, width) +(width)
#define ALL_FIELDS_WIDTH (0u TELEMETRY_FIELDS(PLUS_WIDTH))
#define FIELD_COUNT (sizeof field_props / sizeof field_props[0])
/* every field fits daran_append_properties, and the range of
 * axis0.telemetry.fields ("0..511") has one bit per field */
DARAN_STATIC_ASSERT(FIELD_COUNT <= DARAN_APPEND_MAX, telemetry_fields_fit_one_append);
DARAN_STATIC_ASSERT(FIELD_COUNT == 9u, telemetry_range_has_a_bit_per_field);

bool daran_telemetry_fits(uint32_t fields)
{
    /* the widest line: "@255 " and a time, the fields, then " *255" and
     * the line end */
    size_t width = 5u + DARAN_F32_TEXT_MAX + 5u + (DARAN_REPLY_CRLF ? 2u : 1u);
    if (DARAN_REPLY_MAX >= width + ALL_FIELDS_WIDTH) {
        return true; /* every field set fits: the default */
    }
    for (unsigned bit = 0; bit < FIELD_COUNT; bit++) {
        if (((fields >> bit) & 1u) != 0u) {
            width += field_width[bit];
        }
    }
    return width <= DARAN_REPLY_MAX;
}

daran_result_t daran_telemetry_tick(daran_drive_t *drive, uint32_t tick, uint32_t tick_hz)
{
    daran_value_t period;
    daran_result_t result = daran_get(drive, DARAN_PROP_TELEMETRY_PERIOD, &period);
    if (result != DARAN_OK || !(period.f32 > 0.0f) || tick_hz == 0u) {
        drive->telemetry_due = 1; /* switched on, it reports at once */
        return result;
    }
    /* the first tick with telemetry on reports, whatever the tick count */
    if (!drive->telemetry_due && (int32_t)(tick - drive->telemetry_next) < 0) {
        return DARAN_OK;
    }
    drive->telemetry_due = 0;
    /* the period in whole ticks, at least one, at most about 23 days at 1 kHz */
    float ticks = period.f32 * (float)tick_hz + 0.5f;
    drive->telemetry_next = tick + (ticks < 1.0f ? 1u : (ticks > 2.0e9f ? 2000000000u : (uint32_t)ticks));

    static const daran_prop_t head[] = {DARAN_PROP_TELEMETRY_FIELDS, DARAN_PROP_CAN_NODE_ID};
    daran_value_t settings[2];
    for (unsigned i = 0; i < 2u; i++) {
        result = daran_get(drive, head[i], &settings[i]);
        if (result != DARAN_OK) {
            return result;
        }
    }
    if (!daran_telemetry_fits(settings[0].u32)) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    daran_prop_t props[FIELD_COUNT];
    size_t count = 0;
    for (unsigned bit = 0; bit < FIELD_COUNT; bit++) {
        if (((settings[0].u32 >> bit) & 1u) != 0u) {
            props[count++] = (daran_prop_t)field_props[bit];
        }
    }
    uint8_t checksum = drive->reply_wants_checksum;
    drive->reply_wants_checksum = 1; /* reports always carry one */
    daran_reply_begin(drive);
    daran_reply_text(drive, "@", 1);
    daran_reply_u64(drive, settings[1].u32);
    daran_reply_space(drive);
    daran_reply_f32(drive, (float)tick / (float)tick_hz);
    result = daran_append_properties(drive, props, count);
    if (result == DARAN_OK) {
        daran_reply_end(drive);
    }
    drive->reply_wants_checksum = checksum;
    return result;
}

#else /* !DARAN_ENABLE_TELEMETRY */

daran_result_t daran_telemetry_tick(daran_drive_t *drive, uint32_t tick, uint32_t tick_hz)
{
    (void)drive;
    (void)tick;
    (void)tick_hz;
    return DARAN_OK;
}

#endif /* DARAN_ENABLE_TELEMETRY */
