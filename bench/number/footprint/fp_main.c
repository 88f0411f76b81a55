/* Footprint probe: one program, the variant picked by -DVARIANT (0 nothing,
 * 1 newlib strtof, 2 newlib snprintf("%f") with float printf, 3 our number
 * module). bench/number/footprint.sh links each with newlib-nano and compares. */
#include <stdio.h>
#include <stdlib.h>

#include "number.h"

volatile char g_text[32] = "100.5";
volatile float g_value = 100.5f;
volatile unsigned g_out;

int main(void)
{
    char buf[32];
    float f = 0.0f;
    (void)buf;
    (void)f;
#if VARIANT == 1
    f = strtof((const char *)g_text, NULL);
    g_out = (unsigned)f;
#elif VARIANT == 2
    g_out = (unsigned)snprintf(buf, sizeof buf, "%f", (double)g_value);
#elif VARIANT == 3
    if (daran_parse_f32((const char *)g_text, 5, &f) == DARAN_OK) {
        g_out = (unsigned)daran_format_float(f, buf, sizeof buf);
    }
#endif
    return 0;
}
