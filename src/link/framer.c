/* The framer: bytes -> one line at a time in the instance's line buffer, in
 * one pass over each byte. A field byte is copied and classified, nothing
 * more; every other byte (blank, '*', line end, invalid) ends the field
 * before it, whose offset and length are noted then, so no later stage
 * walks the line to find its fields. Overlong lines, lost bytes and invalid
 * bytes are decided here, once. The checksum's XOR is not taken here: only
 * a line with a '*' needs it, and checksum.c takes it four bytes a step.
 * The framer hands back how far it got and whether a line ended; drive.c
 * runs the line (CHANGELOG.md, issue 20, has the designs measured).
 *
 * The pass keeps its state (field count, where the field began, the '*',
 * the flags) in locals and writes it back once: every byte stored into the
 * line is a char store, which the compiler must assume can change any
 * member of the instance, so state kept there would be reloaded per byte. */
#include "framer.h"

#include "compiler.h"
#include "line.h"
#include "rx_ring.h"

#include <string.h>

void daran_framer_reset(daran_drive_t *drive)
{
    drive->line_len = 0;
    drive->line_flags = 0;
    drive->star_at = DARAN_LINE_MAX;
    drive->fields.count = 0;
}

/* The field bytes a line is made of, almost all of them: '+' (0x2B) to '~'.
 * One range test, which leaves out '*' (0x2A) without a second one; the
 * rarer field bytes '!' to ')' take the other road. */
static bool is_common_field_byte(uint8_t byte)
{
    return (uint8_t)(byte - (uint8_t)'+') <= (uint8_t)('~' - '+');
}

#if DARAN_CHEAP_UNALIGNED_WORDS
/* The bytes of a word that are not common field bytes, as the top bit of
 * each: below '+' (the borrow of the subtraction; ~word keeps bytes of 0x80
 * and up out of that test) or at 0x7F and up (the carry of the addition, or
 * the byte's own top bit). A borrow or carry can flag a byte only beyond one
 * that is flagged rightly, so the first flagged byte in memory order is
 * always right on a little-endian target; on a big-endian one it may be a
 * common byte before it, which the caller decides byte by byte anyway. */
static uint32_t other_bytes_of(uint32_t word)
{
    uint32_t below = (word - 0x2B2B2B2Bu) & ~word;
    uint32_t above = (word + 0x01010101u) | word;
    return (below | above) & 0x80808080u;
}

/* How many bytes come before the first flagged one, in memory order. */
static size_t first_flagged_byte(uint32_t flagged)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    return (size_t)__builtin_clz(flagged) / 8u;
#else
    return (size_t)__builtin_ctz(flagged) / 8u;
#endif
}
#endif

/* Is this byte a line end: '\n', or from the ring the mark of a damaged one? */
static bool is_line_end(uint8_t byte, bool from_ring)
{
    return byte == '\n' || (from_ring && byte == DARAN_RX_DAMAGED_END);
}

/* The one place a field is recorded: the field that began at `start` ends
 * at `at`, the byte after its last; an empty one is no field. Past
 * DARAN_FIELDS_MAX fields nothing more is recorded, and the line has too
 * many fields whatever its command. Returns the new field count. */
static DARAN_ALWAYS_INLINE unsigned close_field(daran_fields_t *fields, unsigned count,
                                                size_t start, size_t at)
{
    if (at > start && count < DARAN_FIELDS_MAX) {
        fields->start[count] = (daran_line_offset_t)start;
        fields->len[count] = (daran_line_offset_t)(at - start);
        count++;
    }
    return count;
}

/* A full line takes only its line end; anything else makes it too long:
 * discard up to the line end, which is still honoured. Returns where the
 * line end is, or `all` when these bytes have none. */
static const uint8_t *skip_overlong(daran_drive_t *drive, const uint8_t *in, const uint8_t *all,
                                    bool from_ring)
{
    const uint8_t *stop = in;
    while (stop != all && !is_line_end(*stop, from_ring)) {
        stop++;
    }
    if (stop != in) {
        drive->line_flags |= DARAN_LINE_TOO_LONG;
    }
    return stop;
}

/* Over 80 lines on purpose: the library's hottest loop (every byte received
 * passes it; perf_insns_per_line holds framing and the ring to 12
 * instructions a byte), kept one function so that its state stays in
 * registers. With the byte decision out of line (`other_byte()`, issue 20)
 * the framer took 358 instructions of `t 1 10 0 25 *83`, folded back in 318
 * (docs/performance.md, "The framer's state in locals"). */
size_t daran_framer_feed(daran_drive_t *drive, const uint8_t *bytes, size_t n, bool from_ring,
                         bool *ended)
{
    if (n == 0u) {
        *ended = false;
        return 0; /* nothing to frame (and bytes may be NULL: no pointer is made from it) */
    }
    char *line = drive->line;
    daran_fields_t *fields = &drive->fields;
    char *out = line + drive->line_len;
    unsigned count = fields->count;
    size_t star_at = drive->star_at;
    /* Where the field being read began: at the next byte, unless the last
     * bytes ended inside a field, which goes on. */
    size_t start = drive->line_len;
    if ((drive->line_flags & DARAN_LINE_IN_FIELD) != 0u) {
        count--;
        start = fields->start[count];
    }
    const uint8_t *in = bytes;
    const uint8_t *all = bytes + n;
    /* Every byte taken before the line end is stored: the line has room for
     * the bytes up to `end`, so the loop checks no length of its own. */
    size_t room = DARAN_LINE_MAX - drive->line_len;
    size_t span = n < room ? n : room;
    const uint8_t *end = bytes + span;
#if DARAN_CHEAP_UNALIGNED_WORDS
    /* where a whole word no longer fits before `end` */
    const uint8_t *words_end = bytes + (span >= 3u ? span - 3u : 0u);
#endif
    bool line_ended = false;
    uint8_t byte;
    for (;;) {
        /* A run of common field bytes is copied and passed over, a word at
         * a time where the target reads unaligned words cheaply; the byte
         * that stops the run is stored with it and decided below. */
#if DARAN_CHEAP_UNALIGNED_WORDS
        if (in < words_end) {
            do {
                uint32_t word;
                memcpy(&word, in, sizeof word);
                memcpy(out, &word, sizeof word);
                uint32_t stops = other_bytes_of(word);
                if (stops != 0u) {
                    size_t run = first_flagged_byte(stops);
                    in += run;
                    out += run;
                    byte = *in++;
                    goto decide;
                }
                in += 4;
                out += 4;
            } while (in < words_end);
        }
#endif
        do {
            if (in == end) {
                if (in == all || (in = skip_overlong(drive, in, all, from_ring)) == all) {
                    goto out_of_bytes;
                }
                /* The full line's line end, never stored: decided below as
                 * if it stood just past the line's last byte. */
                byte = *in++;
                goto decide;
            }
            byte = *in++;
            *out++ = (char)byte;
        } while (is_common_field_byte(byte));
        out--;
    decide:
        if (byte <= ' ' || byte == '*' || byte >= 0x7Fu) {
            if (star_at == DARAN_LINE_MAX) {
                /* it ends the field before it */
                size_t at = (size_t)(out - line);
                count = close_field(fields, count, start, at);
                start = at + 1u;
                if (byte == '*') {
                    star_at = at;
                }
            }
            if (byte != ' ' && byte != '*') {
                if (is_line_end(byte, from_ring)) {
                    if (byte != '\n') {
                        drive->line_flags |= DARAN_LINE_DAMAGED;
                    }
                    line_ended = true;
                    break;
                }
                if (!daran_byte_allowed(byte)) {
                    drive->line_flags |= DARAN_LINE_INVALID_BYTE;
                }
            }
        }
        out++;
    }
out_of_bytes:;
    size_t at = (size_t)(out - line);
    unsigned flags = drive->line_flags & ~DARAN_LINE_IN_FIELD;
    if (!line_ended && star_at == DARAN_LINE_MAX) {
        /* The bytes end inside a field (a text without its line end, or the
         * ring's run): count it, so the line is whole if nothing follows;
         * the next bytes take it up again. */
        unsigned closed = close_field(fields, count, start, at);
        if (closed != count) {
            flags |= DARAN_LINE_IN_FIELD;
        }
        count = closed;
    }
    fields->count = (uint8_t)count;
    drive->line_len = (uint16_t)at;
    drive->line_flags = (uint8_t)flags;
    drive->star_at = (uint16_t)star_at;
    *ended = line_ended;
    return n - (size_t)(all - in);
}
