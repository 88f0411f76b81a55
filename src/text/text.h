/* Text idioms the stages share, each written once (text.c). */
#ifndef DARAN_TEXT_H
#define DARAN_TEXT_H

#include <stdbool.h>
#include <stddef.h>

/* The length of a NUL-terminated text. */
static inline size_t daran_text_len(const char *text)
{
    size_t len = 0;
    while (text[len] != '\0') {
        len++;
    }
    return len;
}

/* Text n (0-based) of a block of NUL-separated texts. */
const char *daran_nth_text(const char *block, unsigned n);

/* Is c the letter @p lower in either case? Command words and the exponent
 * mark are case-insensitive (spec 1); @p lower must be a lower-case letter,
 * the only byte that one bit (0x20) maps to from two letters and nothing else. */
static inline bool daran_letter_is(char c, char lower)
{
    return (char)(c | 0x20) == lower;
}

/* Does the field text[0..len) spell @p word (lower-case letters, at most
 * @p max of them, NUL-terminated when shorter) in either case? A field has
 * neither NUL nor space, the two bytes daran_letter_is() would match with
 * the NUL, so the word's end needs no test of its own inside the loop. */
static inline bool daran_word_is(const char *text, size_t len, const char *word, size_t max)
{
    size_t k = 0;
    for (; k < len; k++) {
        if (k == max || !daran_letter_is(text[k], word[k])) {
            return false;
        }
    }
    return k == max || word[k] == '\0';
}

#endif /* DARAN_TEXT_H */
