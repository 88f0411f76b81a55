/* Flash measurement only (bench/extensions/build.sh): src/ascii/command_table.c
 * as it would compile without port commands and discovery. `h` lists no
 * port command (the count reads as 0, so the loop goes) and `h id
 * properties` calls no discovery; the size difference to command_table.o is
 * what those hooks cost. Never linked into anything. */
#include "handlers.h" /* declared before the macro below replaces discovery */

#define daran_discovery(drive, request, bridged) ((void)(request), (void)(bridged), DARAN_ERR_INVALID_VALUE)
#define port_command_count port_command_count * 0u
#include "../../src/ascii/command_table.c"
