/* The update module's checks of an image: CRC-32 (IEEE 802.3, the one zlib
 * and Python's binascii.crc32 compute) and SHA-256 (FIPS 180-4), both
 * streaming, no table in RAM, no allocation. */
#ifndef DARAN_UPDATE_HASH_H
#define DARAN_UPDATE_HASH_H

#include <stddef.h>
#include <stdint.h>

/* CRC-32 of @p len bytes continued from @p crc (0 to start). */
uint32_t daran_crc32(uint32_t crc, const uint8_t *data, size_t len);

typedef struct daran_sha256 {
    uint32_t state[8];
    uint64_t bytes;     /* hashed so far */
    uint8_t block[64];  /* the part of a block not yet compressed */
} daran_sha256_t;

void daran_sha256_init(daran_sha256_t *sha);
void daran_sha256_update(daran_sha256_t *sha, const uint8_t *data, size_t len);
void daran_sha256_final(daran_sha256_t *sha, uint8_t digest[32]);

#endif /* DARAN_UPDATE_HASH_H */
