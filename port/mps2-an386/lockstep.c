/* Lock-step test harness of the example firmware: daran-fw-lockstep.elf is
 * main.c (the board's firmware, unchanged) plus this file, an add-on through
 * fw.h's door. Time stands still unless the test driver says, as in
 * daran-sim, so that the firmware's replies to a transcript can be compared
 * byte for byte with the host simulator's.
 *
 * The test driver (tests/target/run_transcript.py) sends the transcript's
 * protocol lines unchanged and turns each daran-sim directive into one of
 * these lines, which never reach the core:
 *
 *   !h HZ           control tick rate HZ (daran-sim --tick-hz): the drive
 *                   starts again at that rate; sent before the first line
 *   !t N            run N control ticks (the driver rounds SECONDS x rate
 *                   as daran-sim does)
 *   !p ID           power-cycle when ID is 0 or the drive's id
 *   !f ID KIND      fault: o overtemp, u undervoltage, s stall, v overspeed,
 *                   n nvm-corrupt
 *   !l ID BITS      external load torque, float32 bits in hex
 *   !x              finish: answer nothing more and exit QEMU (status 0)
 *
 * The firmware's RX ISR hands every byte to lockstep_take() first, which
 * spots a '!' at the start of a line, keeps the line here and masks the RX
 * interrupt until the main loop (lockstep_run()) has processed every byte
 * queued before the directive and run it: the UART keeps the next byte
 * (QEMU holds the rest), so order is kept exactly. The drive is reached only
 * through the pointer the firmware passes. */
#include <stdbool.h>
#include <stdint.h>

#include "board.h"
#include "fw.h"

#define DIRECTIVE_MAX 40u

static bool at_line_start = true;
static bool in_directive;
static char directive[DIRECTIVE_MAX];
static uint32_t directive_len;
static volatile bool directive_ready;

static bool lockstep_take(daran_fw_t *fw, uint8_t byte)
{
    (void)fw;
    if (at_line_start && byte == (uint8_t)'!') {
        in_directive = true;
        directive_len = 0u;
    }
    at_line_start = byte == (uint8_t)'\n';
    if (!in_directive) {
        return false;
    }
    if (byte == (uint8_t)'\n') {
        in_directive = false;
        directive_ready = true;
        daran_board_uart0_rx_irq_enable(false);
    } else if (directive_len < DIRECTIVE_MAX) {
        directive[directive_len++] = (char)byte;
    }
    return true;
}

static const char *skip_blanks(const char *p, const char *end)
{
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) {
        p++;
    }
    return p;
}

/* Unsigned number in base 10 or 16; *p moves past it. */
static uint32_t parse_uint(const char **p, const char *end, uint32_t base)
{
    uint32_t v = 0u;
    while (*p < end) {
        char c = **p;
        uint32_t digit;
        if (c >= '0' && c <= '9') {
            digit = (uint32_t)(c - '0');
        } else if (base == 16u && c >= 'a' && c <= 'f') {
            digit = (uint32_t)(c - 'a') + 10u;
        } else {
            break;
        }
        v = v * base + digit;
        (*p)++;
    }
    return v;
}

static bool addressed_here(const daran_fw_t *fw, uint32_t id)
{
    return id == 0u || id == daran_sim_drive_id(&fw->plant);
}

static void run_directive(daran_fw_t *fw, const char *p, const char *end)
{
    char op;
    uint32_t id;
    p = skip_blanks(p + 1, end); /* past '!' */
    if (p == end) {
        return;
    }
    op = *p++;
    p = skip_blanks(p, end);
    switch (op) {
    case 't': {
        uint32_t n = parse_uint(&p, end, 10u);
        while (n-- > 0u) {
            daran_sim_model_tick(&fw->plant.model);
        }
        break;
    }
    case 'h': {
        uint32_t hz = parse_uint(&p, end, 10u);
        if (hz > 0u) {
            daran_sim_drive_init(&fw->plant, 0u, hz);
            daran_fw_start_drive(fw);
        }
        break;
    }
    case 'p':
        id = parse_uint(&p, end, 10u);
        if (addressed_here(fw, id)) {
            daran_sim_drive_power_on(&fw->plant);
            daran_fw_start_drive(fw);
        }
        break;
    case 'f':
        id = parse_uint(&p, end, 10u);
        p = skip_blanks(p, end);
        if (addressed_here(fw, id) && p < end) {
            if (*p == 'o') {
                daran_sim_model_fault(&fw->plant.model, DARAN_SIM_FAULT_OVERTEMP);
            } else if (*p == 'u') {
                daran_sim_model_fault(&fw->plant.model, DARAN_SIM_FAULT_UNDERVOLTAGE);
            } else if (*p == 's') {
                daran_sim_model_fault(&fw->plant.model, DARAN_SIM_FAULT_STALL);
            } else if (*p == 'v') {
                daran_sim_model_fault(&fw->plant.model, DARAN_SIM_FAULT_OVERSPEED);
            } else if (*p == 'n') {
                (void)daran_sim_drive_corrupt_nvm(&fw->plant);
            }
        }
        break;
    case 'l': {
        union {
            uint32_t u;
            float f;
        } load;
        id = parse_uint(&p, end, 10u);
        p = skip_blanks(p, end);
        load.u = parse_uint(&p, end, 16u);
        if (addressed_here(fw, id)) {
            fw->plant.model.ext_torque_nm = load.f;
        }
        break;
    }
    case 'x':
        daran_board_exit(0);
    default:
        break;
    }
}

static bool lockstep_rx_held(daran_fw_t *fw)
{
    (void)fw;
    return directive_ready;
}

static bool lockstep_run(daran_fw_t *fw)
{
    if (!directive_ready) {
        return false;
    }
    /* Lines that arrived before the directive come first. */
    (void)daran_poll(&fw->drive);
    run_directive(fw, directive, directive + directive_len);
    directive_ready = false;
    daran_board_uart0_rx_irq_enable(true);
    return true;
}

static const daran_fw_addon_t lockstep = {
    true, /* no SysTick: time moves by `!t` only */
    lockstep_take,
    lockstep_rx_held,
    lockstep_run,
};

/* Replaces main.c's weak default: this image runs with the harness. */
const daran_fw_addon_t *daran_fw_addon(void)
{
    return &lockstep;
}
