/* The firmware update module (daran_update.h, docs/update.md): the `u?`
 * commands over the port's inactive slot and its journal. What survives a
 * reset or a power cut is in the journal page, written so that a cut in
 * any erase or program step leaves either the old state or the new:
 *   [0, 24)           the open update: magic, size, CRC-32, version,
 *                     hardware id, and the CRC-32 of those 20 bytes
 *   [32 + 4k, +4)     page k of the slot is written whole: 0 (else not)
 *   [page_size - 4)   the image was verified: 0
 * A word counts only when all its bits are programmed, so a cut while one
 * is written leaves the step undone, and it is done again. */
#include <string.h>

#include "command.h"
#include "hal.h"
#include "handlers.h"
#include "hash.h"
#include "number.h"
#include "reply.h"

#include "daran_update.h"

#if DARAN_ENABLE_UPDATE

#define JOURNAL_MAGIC 0x4a4e5244u /* "DRNJ" */
#define RECORD_BYTES 24u
#define PAGE_WORDS_AT 32u
#define DONE 0u

typedef struct record {
    uint32_t size, crc, version, hardware_id;
} record_t;

static uint32_t get_u32(const uint8_t *bytes)
{
    return (uint32_t)bytes[0] | (uint32_t)bytes[1] << 8 | (uint32_t)bytes[2] << 16 |
           (uint32_t)bytes[3] << 24;
}

static void put_u32(uint8_t *bytes, uint32_t value)
{
    for (unsigned i = 0; i < 4u; i++) {
        bytes[i] = (uint8_t)(value >> (8u * i));
    }
}

static const daran_update_port_t *port_of(const daran_update_t *update)
{
    return update->drive->hal->update;
}

static void *ctx_of(const daran_update_t *update)
{
    return update->drive->ctx;
}

static daran_result_t journal_word(const daran_update_t *update, uint32_t at, uint32_t *out)
{
    uint8_t bytes[4];
    daran_result_t result = port_of(update)->read(ctx_of(update), DARAN_UPDATE_JOURNAL, at, bytes, 4u);
    *out = get_u32(bytes);
    return result;
}

static daran_result_t mark_done(const daran_update_t *update, uint32_t at)
{
    static const uint8_t zero[4] = {0};
    return port_of(update)->program(ctx_of(update), DARAN_UPDATE_JOURNAL, at, zero, sizeof zero);
}

static uint32_t page_word_at(uint32_t page)
{
    return PAGE_WORDS_AT + 4u * page;
}

static uint32_t verified_word_at(const daran_update_t *update)
{
    return port_of(update)->page_size - 4u;
}

/* The most pages the journal can say are written. */
static uint32_t journal_pages(const daran_update_port_t *port)
{
    return (port->page_size - PAGE_WORDS_AT - 4u) / 4u;
}

static bool slot_fits(const daran_update_port_t *port, uint32_t size)
{
    return size >= DARAN_UPDATE_HEADER_SIZE && size <= port->slot_size &&
           (size - 1u) / port->page_size < journal_pages(port);
}

/* Both slots as the port's boot control says; what it leaves unset reads 0. */
static void read_slots(const daran_update_t *update, daran_update_slots_t *slots)
{
    memset(slots, 0, sizeof *slots);
    port_of(update)->slots(ctx_of(update), slots);
}

/* ---- reading the journal at init ---- */

static bool read_record(const daran_update_t *update, record_t *record)
{
    uint8_t bytes[RECORD_BYTES];
    if (port_of(update)->read(ctx_of(update), DARAN_UPDATE_JOURNAL, 0u, bytes, sizeof bytes) !=
            DARAN_OK ||
        get_u32(bytes) != JOURNAL_MAGIC || get_u32(bytes + 20) != daran_crc32(0u, bytes, 20u)) {
        return false;
    }
    record->size = get_u32(bytes + 4);
    record->crc = get_u32(bytes + 8);
    record->version = get_u32(bytes + 12);
    record->hardware_id = get_u32(bytes + 16);
    return true;
}

/* The update the journal holds is over: its image runs (a test or kept),
 * or it ran as a test and was not kept. */
static bool update_is_over(const daran_update_t *update, const record_t *record)
{
    daran_update_slots_t slots;
    read_slots(update, &slots);
    unsigned running = slots.running & 1u;
    return (slots.version[running] == record->version &&
            slots.state[running] != DARAN_SLOT_EMPTY) ||
           slots.state[running ^ 1u] == DARAN_SLOT_REVERTED;
}

/* The first page not written whole, as an offset. */
static uint32_t resume_offset(const daran_update_t *update)
{
    uint32_t page_size = port_of(update)->page_size;
    uint32_t pages = (update->size + page_size - 1u) / page_size;
    uint32_t page = 0;
    uint32_t word = 1u;
    while (page < pages && journal_word(update, page_word_at(page), &word) == DARAN_OK &&
           word == DONE) {
        page++;
    }
    return page == pages ? update->size : page * page_size;
}

daran_result_t daran_update_init(daran_update_t *update, daran_drive_t *drive)
{
    if (update == NULL || drive == NULL || drive->hal == NULL || drive->hal->update == NULL) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    const daran_update_port_t *port = drive->hal->update;
    if (port->erase == NULL || port->program == NULL || port->read == NULL ||
        port->commit == NULL || port->confirm == NULL || port->slots == NULL ||
        port->page_size < 256u || port->slot_size < port->page_size) {
        return DARAN_ERR_BAD_ARGUMENT;
    }
    memset(update, 0, sizeof *update);
    update->drive = drive;
    drive->update = update;
    record_t record;
    if (!read_record(update, &record) || update_is_over(update, &record)) {
        return DARAN_OK;
    }
    update->size = record.size;
    update->crc = record.crc;
    update->version = record.version;
    update->hardware_id = record.hardware_id;
    uint32_t verified = 1u;
    if (journal_word(update, verified_word_at(update), &verified) == DARAN_OK &&
        verified == DONE) {
        update->state = DARAN_UPDATE_VERIFIED;
        update->next = update->size;
    } else {
        update->state = DARAN_UPDATE_RECEIVING;
        update->next = resume_offset(update);
    }
    return DARAN_OK;
}

bool daran_update_open(const daran_update_t *update)
{
    return update->state != DARAN_UPDATE_IDLE;
}

/* ---- the steps ---- */

static daran_result_t axis_idle(daran_drive_t *drive)
{
    daran_value_t state;
    daran_result_t result = daran_get(drive, DARAN_PROP_CURRENT_STATE, &state);
    return result != DARAN_OK ? result
           : state.u32 == DARAN_STATE_IDLE ? DARAN_OK
                                           : DARAN_ERR_NOT_IDLE;
}

static daran_result_t field_u32(const daran_request_t *request, unsigned i, uint32_t *out)
{
    daran_field_t field = daran_field_at(request, i);
    uint64_t value;
    daran_result_t result = daran_parse_u64(field.text, field.len, &value);
    if (result == DARAN_OK && value > UINT32_MAX) {
        result = DARAN_ERR_OUT_OF_RANGE;
    }
    *out = (uint32_t)value;
    return result;
}

/* A broadcast step (id 0) loads every drive of a line at once: none
 * answers it, or their answers would collide. */
static void reply_next(daran_update_t *update, const daran_request_t *request)
{
    if (request->motor == 0u) {
        return;
    }
    daran_reply_begin(update->drive);
    daran_reply_u64(update->drive, update->next);
    daran_reply_end(update->drive);
}

static daran_result_t begin(daran_update_t *update, const daran_request_t *request)
{
    record_t asked;
    daran_result_t result = DARAN_OK;
    uint32_t *fields[4] = {&asked.size, &asked.crc, &asked.version, &asked.hardware_id};
    for (unsigned i = 0; i < 4u && result == DARAN_OK; i++) {
        result = field_u32(request, 2u + i, fields[i]);
    }
    if (result != DARAN_OK) {
        return result;
    }
    if (update->state != DARAN_UPDATE_IDLE) {
        /* the same image again: a host resuming; another: abort it first */
        if (asked.size != update->size || asked.crc != update->crc ||
            asked.version != update->version || asked.hardware_id != update->hardware_id) {
            return DARAN_ERR_UPDATE_OPEN;
        }
        reply_next(update, request);
        return DARAN_OK;
    }
    const daran_update_port_t *port = port_of(update);
    if (asked.hardware_id != port->hardware_id || !slot_fits(port, asked.size)) {
        return DARAN_ERR_INVALID_IMAGE;
    }
    result = axis_idle(update->drive);
    if (result != DARAN_OK) {
        return result;
    }
    uint8_t bytes[RECORD_BYTES];
    put_u32(bytes, JOURNAL_MAGIC);
    put_u32(bytes + 4, asked.size);
    put_u32(bytes + 8, asked.crc);
    put_u32(bytes + 12, asked.version);
    put_u32(bytes + 16, asked.hardware_id);
    put_u32(bytes + 20, daran_crc32(0u, bytes, 20u));
    result = port->erase(ctx_of(update), DARAN_UPDATE_JOURNAL, 0u);
    if (result == DARAN_OK) {
        result = port->program(ctx_of(update), DARAN_UPDATE_JOURNAL, 0u, bytes, sizeof bytes);
    }
    if (result != DARAN_OK) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    update->size = asked.size;
    update->crc = asked.crc;
    update->version = asked.version;
    update->hardware_id = asked.hardware_id;
    update->next = 0;
    update->state = DARAN_UPDATE_RECEIVING;
    reply_next(update, request);
    return DARAN_OK;
}

/* A DATA field's characters as bytes, in place (5 characters give 4 bytes,
 * so a byte is never written before its characters are read). Returns the
 * byte count, 0 for a character outside the alphabet or a lone last one. */
static size_t decode_in_place(char *text, size_t len)
{
    uint8_t *out = (uint8_t *)text;
    size_t n = 0;
    for (size_t at = 0; at < len; at += 5u) {
        size_t group = len - at < 5u ? len - at : 5u;
        if (group == 1u) {
            return 0;
        }
        uint32_t value = 0;
        for (size_t k = 0; k < 5u; k++) {
            unsigned digit = 84u; /* a short group is padded with the last digit */
            if (k < group) {
                unsigned c = (unsigned char)text[at + k];
                if (c < (unsigned)DARAN_UPDATE_DATA_FIRST || c > (unsigned)DARAN_UPDATE_DATA_LAST ||
                    c == '*') {
                    return 0;
                }
                digit = c - (unsigned)DARAN_UPDATE_DATA_FIRST - (c > '*' ? 1u : 0u);
            }
            uint64_t wide = (uint64_t)value * 85u + digit;
            if (wide > UINT32_MAX) {
                return 0;
            }
            value = (uint32_t)wide;
        }
        for (size_t k = 0; k + 1u < group; k++) {
            out[n++] = (uint8_t)(value >> (24u - 8u * k));
        }
    }
    return n;
}

/* The bytes at [at, at + len) of the slot equal @p data. */
static daran_result_t slot_holds(const daran_update_t *update, uint32_t at, const uint8_t *data,
                                 size_t len)
{
    uint8_t piece[16];
    for (size_t done = 0; done < len; done += sizeof piece) {
        size_t n = len - done < sizeof piece ? len - done : sizeof piece;
        if (port_of(update)->read(ctx_of(update), DARAN_UPDATE_SLOT, at + (uint32_t)done, piece,
                                  n) != DARAN_OK) {
            return DARAN_ERR_MOTOR_FAULT;
        }
        if (memcmp(piece, data + done, n) != 0) {
            return DARAN_ERR_INVALID_VALUE;
        }
    }
    return DARAN_OK;
}

/* Program [update->next, end) from @p data (which starts at update->next),
 * erasing each page as it is entered and marking each page written whole. */
static daran_result_t program_new(daran_update_t *update, const uint8_t *data, uint32_t end)
{
    const daran_update_port_t *port = port_of(update);
    void *ctx = ctx_of(update);
    uint32_t at = update->next;
    while (at < end) {
        uint32_t page_end = (at / port->page_size + 1u) * port->page_size;
        uint32_t stop = end < page_end ? end : page_end;
        daran_result_t result = DARAN_OK;
        if (at % port->page_size == 0u) {
            result = port->erase(ctx, DARAN_UPDATE_SLOT, at);
        }
        if (result == DARAN_OK) {
            result = port->program(ctx, DARAN_UPDATE_SLOT, at, data + (at - update->next),
                                   stop - at);
        }
        if (result == DARAN_OK) {
            result = slot_holds(update, at, data + (at - update->next), stop - at);
        }
        if (result == DARAN_OK && (stop == page_end || stop == update->size)) {
            result = mark_done(update, page_word_at(at / port->page_size));
        }
        if (result != DARAN_OK) {
            /* the page is written again from its start, erased first */
            update->next = at / port->page_size * port->page_size;
            return DARAN_ERR_MOTOR_FAULT;
        }
        at = stop;
    }
    update->next = end;
    return DARAN_OK;
}

static daran_result_t write_chunk(daran_update_t *update, const daran_request_t *request)
{
    uint32_t offset;
    uint32_t crc;
    daran_result_t result = field_u32(request, 2u, &offset);
    if (result == DARAN_OK) {
        result = field_u32(request, 3u, &crc);
    }
    if (result != DARAN_OK) {
        return result;
    }
    if (update->state != DARAN_UPDATE_RECEIVING) {
        return DARAN_ERR_NO_UPDATE;
    }
    daran_field_t field = daran_field_at(request, 4u);
    /* the line buffer is the instance's, and nothing reads the field after */
    char *text = update->drive->line + (field.text - update->drive->line);
    size_t len = decode_in_place(text, field.len);
    const uint8_t *data = (const uint8_t *)text;
    if (len == 0u) {
        return DARAN_ERR_INVALID_VALUE;
    }
    if (daran_crc32(0u, data, len) != crc) {
        return DARAN_ERR_CHECKSUM_MISMATCH;
    }
    if (offset > update->next || len > update->size - offset) {
        return DARAN_ERR_OUT_OF_RANGE;
    }
    uint32_t end = offset + (uint32_t)len;
    uint32_t seen = end < update->next ? end : update->next;
    result = slot_holds(update, offset, data, seen - offset);
    if (result == DARAN_OK && end > update->next) {
        result = program_new(update, data + (update->next - offset), end);
    }
    if (result != DARAN_OK) {
        return result;
    }
    reply_next(update, request);
    return DARAN_OK;
}

/* Read the slot back: the whole image's CRC-32, the header's fields, the
 * payload's SHA-256 and, where the port wants one, its signature. */
static daran_result_t check_image(const daran_update_t *update)
{
    const daran_update_port_t *port = port_of(update);
    uint8_t header[DARAN_UPDATE_HEADER_SIZE];
    uint8_t piece[64];
    daran_sha256_t sha;
    if (port->read(ctx_of(update), DARAN_UPDATE_SLOT, 0u, header, sizeof header) != DARAN_OK) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    uint32_t crc = daran_crc32(0u, header, sizeof header);
    daran_sha256_init(&sha);
    for (uint32_t at = DARAN_UPDATE_HEADER_SIZE; at < update->size; at += sizeof piece) {
        size_t n = update->size - at < sizeof piece ? update->size - at : sizeof piece;
        if (port->read(ctx_of(update), DARAN_UPDATE_SLOT, at, piece, n) != DARAN_OK) {
            return DARAN_ERR_MOTOR_FAULT;
        }
        crc = daran_crc32(crc, piece, n);
        daran_sha256_update(&sha, piece, n);
    }
    uint8_t digest[32];
    daran_sha256_final(&sha, digest);
    uint16_t flags = (uint16_t)(header[DARAN_UPDATE_AT_FLAGS] |
                                header[DARAN_UPDATE_AT_FLAGS + 1u] << 8);
    bool signed_ok = (flags & DARAN_UPDATE_FLAG_SIGNED) != 0u && port->signature_ok != NULL &&
                     port->signature_ok(ctx_of(update), digest, header + DARAN_UPDATE_AT_SIGNATURE);
    bool good = crc == update->crc && get_u32(header + DARAN_UPDATE_AT_MAGIC) == DARAN_UPDATE_MAGIC &&
                header[DARAN_UPDATE_AT_HEADER_VERSION] == DARAN_UPDATE_HEADER_VERSION &&
                header[DARAN_UPDATE_AT_HEADER_VERSION + 1u] == 0u &&
                get_u32(header + DARAN_UPDATE_AT_PAYLOAD_SIZE) ==
                    update->size - DARAN_UPDATE_HEADER_SIZE &&
                get_u32(header + DARAN_UPDATE_AT_VERSION) == update->version &&
                get_u32(header + DARAN_UPDATE_AT_HARDWARE_ID) == port->hardware_id &&
                memcmp(header + DARAN_UPDATE_AT_SHA256, digest, sizeof digest) == 0 &&
                (signed_ok || !port->require_signature);
    return good ? DARAN_OK : DARAN_ERR_INVALID_IMAGE;
}

static daran_result_t verify(daran_update_t *update)
{
    if (update->state == DARAN_UPDATE_VERIFIED) {
        return DARAN_OK;
    }
    if (update->state != DARAN_UPDATE_RECEIVING || update->next != update->size) {
        return DARAN_ERR_NO_UPDATE;
    }
    daran_result_t result = check_image(update);
    if (result == DARAN_OK) {
        result = mark_done(update, verified_word_at(update)) == DARAN_OK ? DARAN_OK
                                                                         : DARAN_ERR_MOTOR_FAULT;
    }
    if (result == DARAN_OK) {
        update->state = DARAN_UPDATE_VERIFIED;
    }
    return result;
}

static daran_result_t commit(daran_update_t *update)
{
    if (update->state != DARAN_UPDATE_VERIFIED) {
        return DARAN_ERR_NO_UPDATE;
    }
    daran_result_t result = axis_idle(update->drive);
    return result != DARAN_OK ? result : port_of(update)->commit(ctx_of(update));
}

static daran_result_t confirm(daran_update_t *update)
{
    daran_update_slots_t slots;
    read_slots(update, &slots);
    if (slots.state[slots.running & 1u] != DARAN_SLOT_TESTING) {
        return DARAN_ERR_NO_UPDATE;
    }
    return port_of(update)->confirm(ctx_of(update));
}

static daran_result_t abort_update(daran_update_t *update)
{
    if (port_of(update)->erase(ctx_of(update), DARAN_UPDATE_JOURNAL, 0u) != DARAN_OK) {
        return DARAN_ERR_MOTOR_FAULT;
    }
    update->state = DARAN_UPDATE_IDLE;
    update->next = 0;
    return DARAN_OK;
}

/* `us`: state, next offset, size, the running slot, each slot's version and state. */
static daran_result_t status(daran_update_t *update, const daran_request_t *request)
{
    if (request->motor == 0u) {
        return DARAN_OK;
    }
    daran_update_slots_t slots;
    read_slots(update, &slots);
    const uint32_t values[] = {update->state,   update->next,     update->size,
                               slots.running,   slots.version[0], slots.state[0],
                               slots.version[1], slots.state[1]};
    daran_reply_begin(update->drive);
    for (size_t i = 0; i < sizeof values / sizeof values[0]; i++) {
        if (i != 0u) {
            daran_reply_space(update->drive);
        }
        daran_reply_u64(update->drive, values[i]);
    }
    daran_reply_end(update->drive);
    return DARAN_OK;
}

daran_result_t daran_cmd_update(daran_drive_t *drive, const daran_request_t *request)
{
    daran_update_t *update = drive->update;
    if (update == NULL) {
        return DARAN_ERR_NO_UPDATE; /* a port without the update module */
    }
    switch (request->command->arg) {
    case DARAN_UPDATE_OP_BEGIN:
        return begin(update, request);
    case DARAN_UPDATE_OP_WRITE:
        return write_chunk(update, request);
    case DARAN_UPDATE_OP_VERIFY:
        return verify(update);
    case DARAN_UPDATE_OP_COMMIT:
        return commit(update);
    case DARAN_UPDATE_OP_CONFIRM:
        return confirm(update);
    case DARAN_UPDATE_OP_ABORT:
        return abort_update(update);
    default:
        return status(update, request);
    }
}

#else
typedef int daran_update_needs_daran_enable_update; /* ISO C: no empty file */
#endif /* DARAN_ENABLE_UPDATE */
