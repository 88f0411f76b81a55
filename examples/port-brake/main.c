/* daran-port-brake: a drive maker's port with a command and two properties
 * of its own and five vendor properties left out (brake_options.h,
 * brake_port.c), over a printing HAL: every set, move and action the core
 * makes, and every call of the port's own brake driver, is logged on stdout
 * between the replies, so a transcript shows what reached the "hardware".
 *
 *   daran-port-brake [--echo] < lines
 *
 * Protocol lines come from stdin, replies and the log go to stdout. --echo
 * prints each input line as `> line` before its replies, and takes input
 * lines starting with `#` as comments (printed, not sent): the transcript
 * test (transcript.txt) runs it so. On a microcontroller getchar() is the
 * UART interrupt and fwrite() the UART. */
#include <stdio.h>
#include <string.h>

#include "brake_port.h"
#include "daran_ascii.h"

/* ---- the "hardware": a property store ---------------------------------- */

static daran_value_t props[DARAN_PROP_COUNT];
#define PROP(id) props[DARAN_PROP_##id]

/* Paths for the log, from the same lists the core's table is made of. */
#define PATH_ROW(id, path, scope, type, access, range, unit, can) {#scope, path, DARAN_TYPE_##type},
static const struct {
    const char *scope;
    const char *path;
    daran_prop_type_t type;
} paths[DARAN_PROP_COUNT] = {
    DARAN_PROPERTY_LIST(PATH_ROW)
#ifdef DARAN_PORT_PROPERTY_LIST
    DARAN_PORT_PROPERTY_LIST(PATH_ROW)
#endif
};
#undef PATH_ROW

static void log_float(float value)
{
    char text[DARAN_FLOAT_TEXT_MAX];
    size_t len = daran_format_float(value, text, sizeof text);
    fwrite(text, 1, len, stdout);
}

/* ---- the port's own driver: the brake chopper -------------------------- */

static daran_result_t chopper_set_frequency(void *ctx, float hz)
{
    (void)ctx; /* a real driver programs a PWM timer here */
    if (hz == 0.0f) {
        printf("[brake] chopper off\n");
    } else {
        printf("[brake] chopper ");
        log_float(hz);
        printf(" Hz\n");
    }
    PROP(BRAKE_CHOPPER_HZ).f32 = hz;
    return DARAN_OK;
}

static brake_chopper_t chopper = {chopper_set_frequency, NULL};

brake_chopper_t *brake_chopper_of(void *ctx)
{
    (void)ctx; /* one drive, one chopper */
    return &chopper;
}

/* ---- the HAL ----------------------------------------------------------- */

static daran_result_t get(void *ctx, daran_prop_t p, daran_value_t *out)
{
    (void)ctx; /* getters have no side effects and are not logged */
    *out = props[p];
    if (p == DARAN_PROP_BRAKE_TEMPERATURE) {
        /* stands in for a thermistor: the resistor warms with the frequency */
        out->f32 = 25.0f + PROP(BRAKE_CHOPPER_HZ).f32 / 2000.0f;
    }
    return DARAN_OK;
}

static void log_value(daran_prop_t p, daran_value_t v)
{
    printf("%s%s ", paths[p].scope[0] == 'A' ? "axis0." : "", paths[p].path);
    switch (paths[p].type) {
    case DARAN_TYPE_F32:
        log_float(v.f32);
        break;
    case DARAN_TYPE_S32:
        printf("%ld", (long)v.s32);
        break;
    case DARAN_TYPE_U64:
        printf("%llu", (unsigned long long)v.u64);
        break;
    default:
        printf("%lu", (unsigned long)v.u32);
        break;
    }
}

static daran_result_t set(void *ctx, daran_prop_t p, daran_value_t v)
{
    (void)ctx;
    printf("[hal] set ");
    log_value(p, v);
    if (p == DARAN_PROP_BRAKE_CHOPPER_HZ) {
        /* the core checked >= 0 (the row's range); the chopper's upper limit
         * is the port's: refused here, with nothing changed */
        if (!brake_chopper_hz_ok(v.f32)) {
            printf(": refused, above %g Hz\n", (double)BRAKE_CHOPPER_HZ_MAX);
            return DARAN_ERR_OUT_OF_RANGE;
        }
        printf("\n");
        return chopper_set_frequency(NULL, v.f32 + 0.0f);
    }
    printf("\n");
    props[p] = v;
    if (p == DARAN_PROP_REQUESTED_STATE) {
        PROP(CURRENT_STATE) = v; /* state changes take no time here */
    }
    return DARAN_OK;
}

static daran_result_t move(void *ctx, const daran_move_t *m)
{
    static const char *const kinds[] = {"filtered_position", "trapezoid", "passthrough",
                                        "velocity",          "velocity_ramp", "torque",
                                        "torque_ramp",       "impedance"};
    (void)ctx;
    printf("[hal] move %s pos ", kinds[m->kind]);
    log_float(m->pos_deg);
    printf(" vel ");
    log_float(m->vel_rpm);
    printf(" torque ");
    log_float(m->torque_nm);
    printf(" rate ");
    log_float(m->rate);
    if (m->kind == DARAN_MOVE_IMPEDANCE) {
        printf(" kp ");
        log_float(m->kp);
        printf(" kd ");
        log_float(m->kd);
    }
    printf(" given %u\n", (unsigned)m->given);
    /* this drive arrives at once */
    if (m->kind == DARAN_MOVE_FILTERED_POSITION || m->kind == DARAN_MOVE_TRAPEZOID ||
        m->kind == DARAN_MOVE_PASSTHROUGH) {
        PROP(INPUT_POS).f32 = PROP(POS_SETPOINT).f32 = PROP(POS_ESTIMATE).f32 = m->pos_deg;
    }
    return DARAN_OK;
}

static daran_result_t action(void *ctx, daran_action_t a)
{
    static const char *const names[] = {"save_config", "erase_config", "reboot",
                                        "clear_errors", "set_zero", "estop", "feed_watchdog"};
    (void)ctx;
    printf("[hal] action %s\n", names[a]);
    if (a == DARAN_ACTION_ESTOP) {
        PROP(AXIS_ERROR).u32 |= DARAN_FLAG_ESTOP;
        PROP(CURRENT_STATE).u32 = DARAN_STATE_IDLE;
    } else if (a == DARAN_ACTION_CLEAR_ERRORS) {
        PROP(AXIS_ERROR).u32 = 0;
    }
    return DARAN_OK;
}

static void reply(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    fwrite(line, 1, len, stdout);
}

/* ---- the main loop ----------------------------------------------------- */

int main(int argc, char **argv)
{
    static const daran_hal_t hal = {.get = get, .set = set, .move = move, .action = action,
                                    .write = reply};
    static daran_drive_t drive; /* the caller owns all memory */
    int echo = argc > 1 && strcmp(argv[1], "--echo") == 0;
    if (argc > 1 + echo) {
        fprintf(stderr, "usage: %s [--echo] < lines\n", argv[0]);
        return 2;
    }
    PROP(CAN_NODE_ID).u32 = 1;
    PROP(CURRENT_STATE).u32 = DARAN_STATE_CLOSED_LOOP;
    PROP(REQUESTED_STATE).u32 = DARAN_STATE_CLOSED_LOOP;
    PROP(VBUS_VOLTAGE).f32 = 24.0f;
    if (daran_init(&drive, &hal, NULL) != DARAN_OK || brake_port_attach(&drive) != DARAN_OK) {
        fprintf(stderr, "daran-port-brake: the drive refused its set-up\n");
        return 1;
    }

    char seen[512]; /* the input line so far, for --echo */
    size_t seen_len = 0;
    int comment = 0;
    for (int c; (c = getchar()) != EOF;) {
        if (echo && seen_len == 0 && !comment && c == '#') {
            comment = 1;
        }
        if (c == '\n' && echo) {
            printf("%s%.*s\n", comment ? "" : "> ", (int)seen_len, seen);
            seen_len = 0;
            if (comment) {
                comment = 0;
                continue;
            }
        } else if (echo && seen_len < sizeof seen) {
            seen[seen_len++] = (char)c;
        }
        if (!comment) {
            (void)daran_rx_byte(&drive, (uint8_t)c); /* the interrupt side */
            (void)daran_poll(&drive);                /* the main-loop side */
        }
    }
    return 0;
}
