/* Compiled by the option-check tests with impossible -D values: the only
 * thing that may stop it is an #error of daran_config.h. With valid extreme
 * values it compiles, which shows the limits themselves are allowed. */
#include "daran_ascii.h"

int daran_config_probe(void);

int daran_config_probe(void)
{
    return (int)sizeof(daran_drive_t);
}
