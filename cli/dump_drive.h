/* What `daran dump` and `daran restore` both ask of a drive (docs/cli.md,
 * "dump, restore"): its `i` line, one property's value, the `w` line that
 * gives it a value, and a JSON member of a value as the drive printed it. */
#ifndef DARAN_CLI_DUMP_DRIVE_H
#define DARAN_CLI_DUMP_DRIVE_H

#include "cli.h"

/** The drive's `i` line: firmware, hardware, serial number. */
typedef struct drive_version {
    cli_text_line_t line;
    cli_field_t field[3];
} drive_version_t;

/** `i id` into *v; a failure is reported here. */
cli_status_t dump_read_version(cli_session_t *s, uint8_t id, drive_version_t *v);

/** `r` of one property (with or without `axisN.`) into out. Nothing is
 * reported: CLI_DRIVE_ERROR, the drive refused it (*refused says why);
 * another failure is told in why[] (cli_failure_text). */
cli_status_t dump_read_value(cli_session_t *s, uint8_t id, const char *path, char *out,
                             size_t size, daran_result_t *refused, char *why, size_t why_size);

/** The `w` line that gives drive `id` this value: the id in `axisN.` or last. */
void dump_write_line(char *buf, size_t size, uint8_t id, const char *path, const char *value);

/** Write `,"name":` and the drive's number text as JSON (cli_json_number). */
void dump_json_value(FILE *out, const char *name, const char *text, size_t len);

#endif /* DARAN_CLI_DUMP_DRIVE_H */
