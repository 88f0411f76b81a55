/* Text idioms the stages share, each written once. */
#include "text.h"

const char *daran_nth_text(const char *block, unsigned n)
{
    for (; n > 0u; n--) {
        block += daran_text_len(block) + 1u;
    }
    return block;
}
