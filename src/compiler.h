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
#define DARAN_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define DARAN_NOINLINE
#define DARAN_ALWAYS_INLINE inline
#endif

#endif /* DARAN_COMPILER_H */
