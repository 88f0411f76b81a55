/* Host only: a drive's non-volatile memory kept in a file (--nvm DIR). */
#ifndef DARAN_SIM_FILE_STORAGE_H
#define DARAN_SIM_FILE_STORAGE_H

#include "sim_nvm.h"

typedef struct daran_sim_file_storage {
    int fd;
} daran_sim_file_storage_t;

/* Open (creating if needed) @p path as storage; bytes past the end of the
 * file read as erased (0xFF). Returns false with errno set on failure. */
bool daran_sim_file_storage_open(daran_sim_file_storage_t *fs, const char *path,
                                 daran_sim_storage_t *st);
void daran_sim_file_storage_close(daran_sim_file_storage_t *fs);

#endif /* DARAN_SIM_FILE_STORAGE_H */
