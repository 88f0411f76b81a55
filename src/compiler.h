/* What the core asks of the compiler, whichever it is. */
#ifndef DARAN_COMPILER_H
#define DARAN_COMPILER_H

/* A condition the build must meet: a table edit that breaks a handler's
 * assumption stops the compiler (C11 or a C99 negative array size). */
#if defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#define DARAN_STATIC_ASSERT(condition, what) _Static_assert(condition, #what)
#else
#define DARAN_STATIC_ASSERT(condition, what) \
    typedef char daran_static_assert_##what[(condition) ? 1 : -1]
#endif

/* Kept out of a hot loop's function, or folded into it whatever -Os would
 * rather do: the loop's registers decide, not the call's size. */
#if defined(__GNUC__) || defined(__clang__)
#define DARAN_NOINLINE __attribute__((noinline))
#define DARAN_LIKELY(condition) __builtin_expect(!!(condition), 1)
#define DARAN_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define DARAN_NOINLINE
#define DARAN_LIKELY(condition) (condition)
#define DARAN_ALWAYS_INLINE inline
#endif

/* Unaligned 32-bit loads and stores are single instructions (Cortex-M3 and
 * up, x86, AArch64) and the compiler has the bit-scan builtins: the framer
 * then passes over field bytes a word at a time. Cortex-M0 takes bytes. */
#if (defined(__GNUC__) || defined(__clang__)) &&                                   \
    (defined(__ARM_FEATURE_UNALIGNED) || defined(__x86_64__) || defined(__i386__) || \
     defined(__aarch64__))
#define DARAN_CHEAP_UNALIGNED_WORDS 1
#else
#define DARAN_CHEAP_UNALIGNED_WORDS 0
#endif

#endif /* DARAN_COMPILER_H */
