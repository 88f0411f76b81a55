/* Non-volatile memory of a simulated drive: the configuration image (version
 * + CRC) kept in two slots on an abstract byte-addressed storage, saved so
 * that a power cut at any byte loses neither the old nor the new config.
 *
 * Portable C99: no stdio, no heap. The storage is a pair of functions so the
 * same code runs on RAM (tests cut the power at chosen bytes), a file (the
 * host's --nvm DIR) or flash. */
#ifndef DARAN_SIM_NVM_H
#define DARAN_SIM_NVM_H

#include <stdbool.h>
#include <stdint.h>

#include "sim_model.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DARAN_SIM_NVM_SLOT_SIZE 512u
#define DARAN_SIM_NVM_SIZE (2u * DARAN_SIM_NVM_SLOT_SIZE)
/* Format of the image; an image of another version reads as corrupt.
 * 2: the vendor's whole property table (protocol.md 10.2), s32 values. */
#define DARAN_SIM_NVM_VERSION 2u

/* Byte-addressed storage of DARAN_SIM_NVM_SIZE bytes; erased bytes read 0xFF.
 * A write returns false when it did not complete (power lost part-way: the
 * bytes before the cut are written, the rest are not). */
typedef struct daran_sim_storage {
    void *ctx;
    bool (*read)(void *ctx, uint32_t offset, uint8_t *buf, uint32_t len);
    bool (*write)(void *ctx, uint32_t offset, const uint8_t *data, uint32_t len);
} daran_sim_storage_t;

/* Storage in RAM. With power_cut set, the power fails after cut_after more
 * bytes have been written: every later byte is lost until power_cut is
 * cleared. */
typedef struct daran_sim_ram_storage {
    uint8_t bytes[DARAN_SIM_NVM_SIZE];
    bool power_cut;
    uint32_t cut_after;
    uint32_t bytes_written; /* total since init, for tests */
} daran_sim_ram_storage_t;

/* Erase @p ram (all 0xFF, no cut) and make @p st use it. */
void daran_sim_ram_storage_init(daran_sim_ram_storage_t *ram, daran_sim_storage_t *st);

typedef enum daran_sim_nvm_status {
    DARAN_SIM_NVM_LOADED,  /* a stored config was loaded, nothing damaged */
    DARAN_SIM_NVM_BLANK,   /* nothing stored: defaults */
    DARAN_SIM_NVM_DAMAGED  /* a committed image is damaged: defaults */
} daran_sim_nvm_status_t;

/* Boot: load the newest image into m->cfg / m->zero_offset_deg; the
 * defaults when there is none or when a committed image is damaged (bad
 * version, length or CRC, or a value the model or `w` would refuse: see
 * daran_sim_nvm_config_in_range()). */
daran_sim_nvm_status_t daran_sim_nvm_load(const daran_sim_storage_t *st, daran_sim_model_t *m);

/* True when every configuration value in @p cfg is one a `w` line would
 * take: each is written through a real `w` into a scratch protocol
 * instance (the core's own parser and range rules, as built). Otherwise
 * false, and *first_bad (if not NULL) names the first property refused.
 * Boot uses it: a stored image that fails it is damage. */
bool daran_sim_nvm_config_in_range(const daran_value_t cfg[DARAN_PROP_COUNT],
                                   daran_prop_t *first_bad);

/* `ss`: write the configuration of @p m into the slot not holding the newest
 * image, committing it with its last byte. False if the storage failed. */
bool daran_sim_nvm_save(const daran_sim_storage_t *st, const daran_sim_model_t *m);

/* `se`: invalidate both slots, older first, so a cut part-way leaves the
 * newest image in place. */
bool daran_sim_nvm_erase(const daran_sim_storage_t *st);

/* The nvm-corrupt fault: damage every committed image (or, when nothing is
 * stored, leave a damaged one) so the next boot finds it. */
bool daran_sim_nvm_corrupt(const daran_sim_storage_t *st);

/* Bytes one save writes (for tests that cut the power at each of them). */
uint32_t daran_sim_nvm_save_size(void);

/* CRC-32 (IEEE 802.3, reflected), as stored in the image header. */
uint32_t daran_sim_crc32(const uint8_t *data, uint32_t len, uint32_t crc);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_NVM_H */
