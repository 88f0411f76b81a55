/* Flash measurement only (bench/extensions/build.sh): src/ascii/drive.c as it
 * would compile without port commands. The port lookup never finds one, so
 * the compiler drops the port branch of the dispatch; the size difference
 * to drive.o is what that hook costs. Never linked into anything. */
#include "command.h" /* declared before the macro below replaces the lookup */

#define daran_find_port_command(drive, word) ((void)(drive), (void)(word), (const struct daran_port_command *)0)
#include "../../src/ascii/drive.c"
