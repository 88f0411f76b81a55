/* Telemetry reports (protocol.md 11.2): `@<id> <t> <values> *N`, one line
 * every `axis0.telemetry.period` seconds (whole control ticks, at least
 * one), with the values `axis0.telemetry.fields` selects, in bit order. The
 * port calls daran_telemetry_tick() once per control tick from the context
 * that runs daran_poll(), so a report never falls inside a reply. */
#include "internal.h"

#include "daran_port.h"

/* What each field bit reports, in bit order. */
static const daran_prop_t field_props[] = {
    DARAN_PROP_POS_ESTIMATE,    DARAN_PROP_VEL_ESTIMATE,      DARAN_PROP_TORQUE_ESTIMATE,
    DARAN_PROP_IQ_MEASURED,     DARAN_PROP_VBUS_VOLTAGE,      DARAN_PROP_FET_TEMPERATURE,
    DARAN_PROP_MOTOR_TEMPERATURE, DARAN_PROP_AXIS_ERROR,      DARAN_PROP_TRAJECTORY_DONE,
};
#define FIELD_COUNT (sizeof field_props / sizeof field_props[0])

/* The longest text of each kind of value, with its space: a float, the
 * error register, the trajectory flag. */
#define FLOAT_WIDTH (1u + DARAN_F32_TEXT_MAX)
#define ERROR_WIDTH (1u + 10u)
#define FLAG_WIDTH (1u + 1u)
/* "@<id> <t>": the id has 3 digits at most (DARAN_MOTOR_ID_MAX <= 255). */
#define HEAD_WIDTH (1u + 3u + FLOAT_WIDTH)
/* What reply.c keeps for " *NNN" and the line end. */
#define TAIL_WIDTH (5u + (DARAN_REPLY_CRLF ? 2u : 1u))

bool daran_telemetry_fits(uint32_t fields)
{
    size_t width = HEAD_WIDTH + TAIL_WIDTH;
    for (unsigned bit = 0; bit < FIELD_COUNT; bit++) {
        if (((fields >> bit) & 1u) != 0u) {
            width += bit < 7u ? FLOAT_WIDTH : (bit == 7u ? ERROR_WIDTH : FLAG_WIDTH);
        }
    }
    return width <= DARAN_REPLY_MAX;
}

daran_result_t daran_telemetry_tick(daran_drive_t *drive, uint32_t tick, uint32_t tick_hz)
{
    daran_value_t period;
    daran_result_t result = daran_get(drive, DARAN_PROP_TELEMETRY_PERIOD, &period);
    if (result != DARAN_OK || !(period.f32 > 0.0f) || tick_hz == 0u) {
        drive->telemetry_next = tick; /* switched on, it reports at once */
        return result;
    }
    if ((int32_t)(tick - drive->telemetry_next) < 0) {
        return DARAN_OK;
    }
    /* the period in whole ticks, at least one, at most about 24 days at 1 kHz */
    float ticks = period.f32 * (float)tick_hz + 0.5f;
    uint32_t step = ticks < 1.0f ? 1u : (ticks > 2.0e9f ? 2000000000u : (uint32_t)ticks);
    drive->telemetry_next = tick + step;

    daran_value_t fields;
    daran_value_t id;
    daran_value_t values[FIELD_COUNT];
    result = daran_get(drive, DARAN_PROP_TELEMETRY_FIELDS, &fields);
    if (result == DARAN_OK) {
        result = daran_get(drive, DARAN_PROP_CAN_NODE_ID, &id);
    }
    for (unsigned bit = 0; bit < FIELD_COUNT && result == DARAN_OK; bit++) {
        if (((fields.u32 >> bit) & 1u) != 0u) {
            result = daran_get(drive, field_props[bit], &values[bit]);
        }
    }
    if (result != DARAN_OK || !daran_telemetry_fits(fields.u32)) {
        return result != DARAN_OK ? result : DARAN_ERR_OUT_OF_RANGE;
    }
    uint8_t checksum = drive->reply_checksum;
    drive->reply_checksum = 1; /* reports always carry one */
    daran_reply_begin(drive);
    daran_reply_text(drive, "@", 1);
    daran_reply_u64(drive, id.u32);
    daran_reply_space(drive);
    daran_reply_f32(drive, (float)tick / (float)tick_hz);
    for (unsigned bit = 0; bit < FIELD_COUNT; bit++) {
        if (((fields.u32 >> bit) & 1u) != 0u) {
            daran_reply_space(drive);
            if (bit < 7u) {
                daran_reply_f32(drive, values[bit].f32);
            } else {
                daran_reply_u64(drive, values[bit].u32);
            }
        }
    }
    daran_reply_end(drive);
    drive->reply_checksum = checksum;
    return DARAN_OK;
}
