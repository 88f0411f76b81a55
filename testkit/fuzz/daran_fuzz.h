/* The pieces of the adopter's fuzz harness (daran_ascii_add_fuzz_target):
 * the checks it makes of every reply and every request line, the reader that
 * turns a recording into seed inputs, and the libFuzzer entry point that runs
 * the adopter's test port (daran_test_port.h) through the core.
 *
 * Compiled per core target, against the adopter's options header. Host only
 * (stdio). The checks are written from docs/protocol.md and
 * docs/security.md, not taken from the core, so a core or a port that breaks
 * the protocol is caught. */
#ifndef DARAN_FUZZ_H
#define DARAN_FUZZ_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Invariant 4 for one reply line as the core hands it to the reply sink:
 * NULL when it is well-formed, otherwise what is wrong with it. Well-formed:
 * 1..DARAN_REPLY_MAX bytes; a payload of printable ASCII (0x20..0x7E), not
 * empty; the line end of DARAN_REPLY_CRLF (CR LF, or LF) once, at its end; at
 * most one '*', which opens a ` *N` tail at the very end, N the XOR of every
 * byte before the '*' in decimal without leading zeros; a payload that
 * starts with "error" is `error: ` and a phrase of protocol.md section 8. */
const char *daran_fuzz_reply_problem(const char *line, size_t len);

/** Not a motor id: the line is answered (or ignored, when blank) by every
 * drive, whatever its id. */
#define DARAN_FUZZ_EVERY_DRIVE (-1)

/** The motor id a request line (without its '\n') is for, by this harness's
 * own reading of protocol.md (sections 1-3 and 8, D7-D9, D39): the
 * whole-line checks (length, characters, checksum), a command word of the
 * build (the vendor's, less those its options compiled out, and the port's
 * @p words, @p word_count of them), then the id field (`axisN.` for `r`/`w`
 * of an axis path, the trailing id of a system path, field 1 otherwise),
 * an exact decimal 0..DARAN_MOTOR_ID_MAX. DARAN_FUZZ_EVERY_DRIVE when any
 * of these fails or the line is blank. */
int daran_fuzz_line_motor(const char *line, size_t len, const char *const *words,
                          size_t word_count);

/** Seeds of a recording: its request lines (`SECONDS<TAB>line`) joined by
 * '\n', cut into inputs of at most DARAN_FUZZ_SEED_MAX bytes of whole lines
 * (a longer line is an input of its own). `#` comments, reply lines
 * (`<SECONDS<TAB>...`) and empty lines are skipped. */
#define DARAN_FUZZ_SEED_MAX 1024u

typedef struct daran_fuzz_recording {
    const char *text; /**< the whole file */
    size_t len;
    size_t pos;       /**< where the next seed starts reading */
    unsigned line_no; /**< file lines read so far */
} daran_fuzz_recording_t;

/** Start reading @p text (@p len bytes, the whole recording). */
void daran_fuzz_recording_open(daran_fuzz_recording_t *rec, const char *text, size_t len);

/** The next seed into @p out (room for @p cap bytes; @p cap at least the
 * recording's length suffices). Returns 1 and sets @p *len, @p *first and
 * @p *last (the file lines of its first and last request); 0 at the end;
 * -1 for a line that is none of the recording's forms (@p *first is its file
 * line) or a seed that does not fit @p cap. */
int daran_fuzz_recording_next(daran_fuzz_recording_t *rec, char *out, size_t cap, size_t *len,
                              unsigned *first, unsigned *last);

/** Lets @p ms milliseconds of drive time pass after every request line when
 * the test port gives advance(). */
#ifndef DARAN_FUZZ_ADVANCE_MS
#define DARAN_FUZZ_ADVANCE_MS 2u
#endif

/* ---- what both targets (lines and frames) do alike (fuzz_rows.c) ---- */

struct daran_test_port; /* daran_test_port.h */
struct daran_recorder;  /* daran_recorder.h */

/** The name of the input being run, printed with a violated invariant (the
 * replay sets it; NULL: none). */
void daran_fuzz_set_input_name(const char *name);

/** What is missing from the test port (@p port may be NULL) for any target
 * to run it (its HAL's four functions, reset()): NULL when nothing. */
const char *daran_fuzz_port_problem(const struct daran_test_port *port);

/** The start of an input: the port's reset(), then @p drive bound to
 * @p shim (the recording HAL's functions with the harness's reply sink, and
 * its CAN functions if it has them) with @p rec as context: the port's HAL
 * wrapped in @p rec (getters logged too). NULL when it went so, else what
 * failed. */
const char *daran_fuzz_start_drive(const struct daran_test_port *port, struct daran_recorder *rec,
                                   daran_drive_t *drive, const daran_hal_t *shim);

/** The first line of a violation's report on stderr: the banner, @p front_end
 * ("CAN, " or ""), the port's name and the input's, then @p fmt with @p ap. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((format(printf, 3, 0)))
#endif
void daran_fuzz_report_violation(const char *front_end, const struct daran_test_port *port,
                                 const char *fmt, va_list ap);

/** The HAL calls @p rec logged, on stderr after @p label, one a line,
 * aligned under the first. */
void daran_fuzz_report_calls(const struct daran_recorder *rec, const char *label);

/** What the inputs run so far exercised (the replay prints it: a corpus
 * that never reaches a HAL call or another drive's line checks little). The
 * CAN target counts frames: run, to ignore, for another node, with a call. */
typedef struct daran_fuzz_totals {
    size_t lines;         /**< request lines run */
    size_t answered_error; /**< ... answered with an error */
    size_t other_drive;   /**< ... read as for another drive */
    size_t mutating;      /**< ... that made a setter, move or action call */
    size_t refused;       /**< ... whose setter, move or action the HAL refused */
} daran_fuzz_totals_t;

const daran_fuzz_totals_t *daran_fuzz_totals(void);

/** What daran_hal.h promises the HAL about one call (property ids of the
 * build and not left out, no write of a read-only row, finite floats, 0/1
 * bools, valid move kinds and actions, moves only when @p may_move, if
 * @p state_known): NULL when @p call keeps it, else what it breaks. */
struct daran_call; /* daran_recorder.h */
const char *daran_fuzz_call_problem(const struct daran_call *call, bool state_known, bool may_move);

/** Whether the options header leaves @p prop out (DARAN_OMIT_PROPERTIES). */
bool daran_fuzz_prop_omitted(daran_prop_t prop);

/** The row of the build at CAN address @p address (not 0, not left out). */
bool daran_fuzz_can_row(uint32_t address, daran_prop_t *prop);

/** The CAN type code of @p prop's row: f32 0, u32 and bool 3, s32 4. */
unsigned daran_fuzz_can_type_code(daran_prop_t prop);

/** Built-in seeds of the CAN fuzz target (frames the vendor's clients send,
 * and the settings that wake the heartbeat and the node guard): seed
 * @p index into @p out (room for @p cap bytes); its length, 0 past the
 * last. */
size_t daran_fuzz_can_seed(size_t index, uint8_t *out, size_t cap);

#define DARAN_FUZZ_CAN_RECORD 12u

/** The libFuzzer entry point: @p data is the bytes a host sends (the CAN
 * target: records of DARAN_FUZZ_CAN_RECORD bytes, fuzz_can_target.c). */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_FUZZ_H */
