/* --nvm DIR: each drive's non-volatile memory in DIR/drive-K.nvm and its
 * shaft angle in DIR/drive-K.shaft, so a saved config and a set zero survive
 * a restart. */
#ifndef SIM_NVM_DIR_H
#define SIM_NVM_DIR_H

#include <stdbool.h>

/* Open (or create) the NVM files and boot the drives from them; 0, or 2
 * (said on stderr) when one cannot be opened. */
int open_nvm(const char *dir);
/* The shaft angles saved at the last exit (a missing file: 0 deg). */
void load_shafts(const char *dir);
/* Write the shaft angles, each file replaced whole; false (said on stderr)
 * when one could not be written. */
bool save_shafts(const char *dir);

#endif /* SIM_NVM_DIR_H */
