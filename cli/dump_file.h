/* The file `daran dump` writes and `daran restore` reads (docs/cli.md,
 * "dump, restore"): `#` comments, among them the header, and protocol `w`
 * lines. Which properties are configuration (restored) and which are not
 * is decided here, once, for both commands. */
#ifndef DARAN_CLI_DUMP_FILE_H
#define DARAN_CLI_DUMP_FILE_H

#include "cli.h"

/** The header comment that names the drive's firmware version: `# firmware
 * 100, hardware 3, serial number 2026000001` (the fields of `i`). */
#define DUMP_FIRMWARE_HEAD "# firmware "

/** The property that is the drive's address: recorded, never restored. */
#define DUMP_NODE_ID_PATH "config.can_node_id"

/** Why the read-write property `path` (with or without `axisN.`) is not
 * configuration and is never restored; NULL when it is configuration.
 * `range` is discovery's range text ("" when unknown): a property that
 * takes only 0 is an error register. The node id has its own reason. */
const char *dump_not_restored_why(const char *path, const char *range);

/** `path` without its `axisN.` prefix (itself when it has none). */
const char *dump_bare_path(const char *path);


#define DUMP_VALUE_MAX 48u

/** One `w` line of a file. */
typedef struct dump_entry {
    /** as sent to the drive restored: `axisID.x` (the file's axisN replaced;
     * one more byte, for an ID of more digits), or `x` (the id last) */
    char path[CLI_PATH_MAX + 1u];
    bool axis;                 /**< the path has an `axisN.` prefix */
    char value[DUMP_VALUE_MAX]; /**< the value as written */
    daran_client_value_t parsed;
    unsigned line; /**< its line number in the file */
} dump_entry_t;

/** A whole file, read before the drive is touched. */
typedef struct dump_file {
    dump_entry_t entries[CLI_PROPERTIES_MAX];
    size_t count;
    char firmware[DUMP_VALUE_MAX]; /**< from the header; "" when it names none */
} dump_file_t;

/** Read `name` into *out, each path as it goes to drive `id` (a dump of
 * drive 2 restored into drive 3 writes `axis3.`). Anything but blank lines,
 * comments and `w` lines of configuration is refused with `name:line: what`
 * (CLI_USAGE), as is a file that cannot be read. */
cli_status_t dump_file_read(const char *name, uint8_t id, dump_file_t *out);

#endif /* DARAN_CLI_DUMP_FILE_H */
