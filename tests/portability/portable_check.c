/* The same numbers and protocol lines through the core on two machines: the
 * host and a 16-bit-int AVR under simavr (tools/ci.d/33-avr.sh). The output
 * of both must be byte-identical, so any place where the core leans on int,
 * size_t or long being 32 bits shows up as a difference. A reply's CR is
 * written as '|', so every record line ends in something other than '.'. */
#include <stdint.h>
#include <string.h>

#include "daran_ascii.h"
#include "daran_port.h"
#include "number.h" /* the core's parsers, as the unit tests reach them */
#include "stub_hal.h"

void portable_emit(const char *text, size_t len); /* the platform's output */

static void emit_text(const char *text)
{
    portable_emit(text, strlen(text));
}

static void emit_uint(uint64_t value)
{
    char buf[DARAN_UINT_TEXT_MAX];
    portable_emit(buf, daran_format_uint(value, buf, sizeof buf));
}

static void emit_hex32(uint32_t value)
{
    char buf[8];
    for (unsigned i = 0; i < 8u; i++) {
        buf[i] = "0123456789abcdef"[(value >> (28u - 4u * i)) & 15u];
    }
    portable_emit(buf, sizeof buf);
}

static void reply_sink(void *ctx, const char *line, size_t len)
{
    (void)ctx;
    for (size_t i = 0; i < len; i++) {
        portable_emit(line[i] == '\r' ? "|" : &line[i], 1);
    }
}

static const daran_hal_t reply_sink_port = {DARAN_STUB_HAL_FUNCTIONS, .write = reply_sink};

static const char *const numbers[] = {
    "20.5", "0.5", "1.25", "9600", "115200", "100000", "-1", "-0", "0.1", "1e-5",
    "123456789", "3.4028235e38", "3.4028236e38", "1.17549435e-38", "1e-45", "7e-46",
    "18446744073709551615", "18446744073709551616", "1e19", "65536", "65535.5",
    "4294967296", "0.000001234", "90.000000", "1.0000000000000000000001", "12e", "",
};

/* Lines a host sends, across every stage the core has. */
static const char *const lines[] = {
    "t 1 10 0 25 *83", "q 1 50.0 7.5 2.5", "v 1 12.5 2.5 2", "d 1 10 0 0.5 0.1 0.01",
    "w config.uart_baudrate 9600 1", "r config.uart_baudrate 1",
    "w axis1.controller.config.pos_gain 20.5", "r axis1.controller.config.pos_gain",
    "w axis1.motor.config.direction -1", "r axis1.motor.config.direction",
    "w axis1.config.can_node_id 64", "ms 1 120 5 10", "mq 1 1", "f 1 *87", "e 1",
    "h 1 properties axis0.output_shaft.", "r axis1.nonsense", "t 1 1x0", "t 1 10 0 25 *84",
    "i 1",
};

void portable_check(void);

void portable_check(void)
{
    for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; i++) {
        const char *text = numbers[i];
        float f = 0.0f;
        uint64_t u = 0;
        char buf[DARAN_FLOAT_TEXT_MAX];
        uint32_t bits;
        daran_result_t rf = daran_parse_f32(text, strlen(text), &f);
        daran_result_t ru = daran_parse_u64(text, strlen(text), &u);
        memcpy(&bits, &f, sizeof bits);
        emit_text(text);
        emit_text(" f32 ");
        emit_uint((uint64_t)rf);
        emit_text(" ");
        emit_hex32(bits);
        emit_text(" ");
        portable_emit(buf, daran_format_float(f, buf, sizeof buf));
        emit_text(" u64 ");
        emit_uint((uint64_t)ru);
        emit_text(" ");
        emit_uint(u);
        emit_text("\n");
    }
    static daran_stub_t stub;
    static daran_drive_t drive;
    daran_stub_init(&stub, 1);
    if (daran_init(&drive, &reply_sink_port, &stub) != DARAN_OK) {
        emit_text("init failed\n");
        return;
    }
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        emit_text(lines[i]);
        emit_text(" ->\n");
        daran_process_line(&drive, lines[i], strlen(lines[i]));
        emit_text("moves ");
        emit_uint(stub.moves);
        emit_text(" sets ");
        emit_uint(stub.sets);
        emit_text("\n");
    }
    emit_text("end\n");
}

#if defined(__AVR__)
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

void portable_emit(const char *text, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        while (!(UCSR0A & (1 << UDRE0))) {
        }
        UDR0 = (uint8_t)text[i];
    }
}

int main(void)
{
    UCSR0B = (1 << TXEN0);
    portable_check();
    cli();
    sleep_cpu(); /* simavr ends the run: sleeping with interrupts off */
    return 0;
}
#else
#include <stdio.h>

void portable_emit(const char *text, size_t len)
{
    fwrite(text, 1, len, stdout);
}

int main(void)
{
    portable_check();
    return 0;
}
#endif
