/* A float32's bits and back, for tests that compare numbers exactly. */
#ifndef DARAN_FLOAT_BITS_H
#define DARAN_FLOAT_BITS_H

#include <stdint.h>
#include <string.h>

static inline uint32_t daran_bits_of(float f)
{
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    return bits;
}

static inline float daran_float_of(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

#endif /* DARAN_FLOAT_BITS_H */
