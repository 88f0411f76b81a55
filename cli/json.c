/* JSON output (--json): strings escaped, the drive's numbers kept as it
 * printed them. */
#include <string.h>

#include "cli.h"

void cli_json_string(FILE *out, const char *s, size_t len)
{
    fputc('"', out);
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '"' || c == '\\') {
            fputc('\\', out);
            fputc(c, out);
        } else if (c < 0x20 || c == 0x7f) {
            fprintf(out, "\\u%04x", c);
        } else {
            fputc(c, out);
        }
    }
    fputc('"', out);
}

void cli_json_number(FILE *out, const char *s, size_t len)
{
    daran_client_number_t n;
    /* JSON has no nan or infinity; a drive prints them as words. */
    bool finite = daran_client_parse_number(s, len, &n) == DARAN_OK &&
                  (n.is_integer || (n.f32 - n.f32 == 0.0f));
    if (finite) {
        fwrite(s, 1, len, out);
    } else {
        cli_json_string(out, s, len);
    }
}

void cli_json_member(FILE *out, const char *name, const char *text)
{
    fprintf(out, ",\"%s\":", name);
    cli_json_string(out, text, strlen(text));
}
