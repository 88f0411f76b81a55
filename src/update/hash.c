/* CRC-32 and SHA-256 for the update module (hash.h). Both are written for
 * flash over speed: the CRC goes a nibble at a time through a 16-entry
 * table, SHA-256 keeps its 64 round constants and one schedule array of 16
 * words on the stack. */
#include "hash.h"

#include <string.h>

#include "daran_config.h"

#if DARAN_ENABLE_UPDATE

uint32_t daran_crc32(uint32_t crc, const uint8_t *data, size_t len)
{
    static const uint32_t nibble[16] = {
        0x00000000u, 0x1db71064u, 0x3b6e20c8u, 0x26d930acu, 0x76dc4190u, 0x6b6b51f4u,
        0x4db26158u, 0x5005713cu, 0xedb88320u, 0xf00f9344u, 0xd6d6a3e8u, 0xcb61b38cu,
        0x9b64c2b0u, 0x86d3d2d4u, 0xa00ae278u, 0xbdbdf21cu};
    crc = ~crc;
    for (size_t i = 0; i < len; i++) {
        crc ^= data[i];
        crc = (crc >> 4) ^ nibble[crc & 15u];
        crc = (crc >> 4) ^ nibble[crc & 15u];
    }
    return ~crc;
}

static const uint32_t round_constant[64] = {
    0x428a2f98u, 0x71374491u, 0xb5c0fbcfu, 0xe9b5dba5u, 0x3956c25bu, 0x59f111f1u, 0x923f82a4u,
    0xab1c5ed5u, 0xd807aa98u, 0x12835b01u, 0x243185beu, 0x550c7dc3u, 0x72be5d74u, 0x80deb1feu,
    0x9bdc06a7u, 0xc19bf174u, 0xe49b69c1u, 0xefbe4786u, 0x0fc19dc6u, 0x240ca1ccu, 0x2de92c6fu,
    0x4a7484aau, 0x5cb0a9dcu, 0x76f988dau, 0x983e5152u, 0xa831c66du, 0xb00327c8u, 0xbf597fc7u,
    0xc6e00bf3u, 0xd5a79147u, 0x06ca6351u, 0x14292967u, 0x27b70a85u, 0x2e1b2138u, 0x4d2c6dfcu,
    0x53380d13u, 0x650a7354u, 0x766a0abbu, 0x81c2c92eu, 0x92722c85u, 0xa2bfe8a1u, 0xa81a664bu,
    0xc24b8b70u, 0xc76c51a3u, 0xd192e819u, 0xd6990624u, 0xf40e3585u, 0x106aa070u, 0x19a4c116u,
    0x1e376c08u, 0x2748774cu, 0x34b0bcb5u, 0x391c0cb3u, 0x4ed8aa4au, 0x5b9cca4fu, 0x682e6ff3u,
    0x748f82eeu, 0x78a5636fu, 0x84c87814u, 0x8cc70208u, 0x90befffau, 0xa4506cebu, 0xbef9a3f7u,
    0xc67178f2u};

static uint32_t rotr(uint32_t x, unsigned n)
{
    return (x >> n) | (x << (32u - n));
}

/* One 64-byte block; the schedule is kept as a ring of 16 words. */
static void compress(uint32_t state[8], const uint8_t block[64])
{
    uint32_t w[16];
    uint32_t v[8];
    for (unsigned i = 0; i < 16u; i++) {
        w[i] = (uint32_t)block[4u * i] << 24 | (uint32_t)block[4u * i + 1u] << 16 |
               (uint32_t)block[4u * i + 2u] << 8 | block[4u * i + 3u];
    }
    memcpy(v, state, sizeof v);
    for (unsigned i = 0; i < 64u; i++) {
        if (i >= 16u) {
            uint32_t w15 = w[(i - 15u) & 15u];
            uint32_t w2 = w[(i - 2u) & 15u];
            w[i & 15u] += (rotr(w15, 7) ^ rotr(w15, 18) ^ (w15 >> 3)) + w[(i - 7u) & 15u] +
                          (rotr(w2, 17) ^ rotr(w2, 19) ^ (w2 >> 10));
        }
        uint32_t t1 = v[7] + (rotr(v[4], 6) ^ rotr(v[4], 11) ^ rotr(v[4], 25)) +
                      ((v[4] & v[5]) ^ (~v[4] & v[6])) + round_constant[i] + w[i & 15u];
        uint32_t t2 = (rotr(v[0], 2) ^ rotr(v[0], 13) ^ rotr(v[0], 22)) +
                      ((v[0] & v[1]) ^ (v[0] & v[2]) ^ (v[1] & v[2]));
        memmove(&v[1], &v[0], 7u * sizeof v[0]);
        v[4] += t1;
        v[0] = t1 + t2;
    }
    for (unsigned i = 0; i < 8u; i++) {
        state[i] += v[i];
    }
}

void daran_sha256_init(daran_sha256_t *sha)
{
    static const uint32_t initial[8] = {0x6a09e667u, 0xbb67ae85u, 0x3c6ef372u, 0xa54ff53au,
                                        0x510e527fu, 0x9b05688cu, 0x1f83d9abu, 0x5be0cd19u};
    memcpy(sha->state, initial, sizeof sha->state);
    sha->bytes = 0;
}

void daran_sha256_update(daran_sha256_t *sha, const uint8_t *data, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        sha->block[sha->bytes % 64u] = data[i];
        sha->bytes++;
        if (sha->bytes % 64u == 0u) {
            compress(sha->state, sha->block);
        }
    }
}

void daran_sha256_final(daran_sha256_t *sha, uint8_t digest[32])
{
    uint64_t bits = sha->bytes * 8u;
    uint8_t pad = 0x80u;
    daran_sha256_update(sha, &pad, 1u);
    pad = 0;
    while (sha->bytes % 64u != 56u) {
        daran_sha256_update(sha, &pad, 1u);
    }
    uint8_t length[8];
    for (unsigned i = 0; i < 8u; i++) {
        length[i] = (uint8_t)(bits >> (56u - 8u * i));
    }
    daran_sha256_update(sha, length, sizeof length);
    for (unsigned i = 0; i < 32u; i++) {
        digest[i] = (uint8_t)(sha->state[i / 4u] >> (24u - 8u * (i % 4u)));
    }
}

#else
typedef int daran_hash_needs_daran_enable_update; /* ISO C: no empty file */
#endif /* DARAN_ENABLE_UPDATE */
