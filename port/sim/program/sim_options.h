/* daran-sim's command line, as --help describes it. */
#ifndef SIM_OPTIONS_H
#define SIM_OPTIONS_H

#include <stdbool.h>

typedef struct sim_options {
    unsigned long drives;    /* --drives N, 1..16 */
    unsigned long tick_hz;   /* --tick-hz HZ */
    unsigned long every;     /* --trace-every N */
    const char *nvm_dir;     /* --nvm DIR, or NULL */
    const char *trace_path;  /* --trace FILE, or NULL */
    const char *record_path; /* --record FILE, or NULL */
    bool pty;                /* --pty */
    bool echo;               /* --echo */
    bool can;                /* --can */
    bool slcan;              /* --slcan */
    bool usbcan;             /* --usbcan */
    bool bridge;             /* --bridge */
} sim_options_t;

/* Fill @p o from the command line: -1 to run, else the exit status (0
 * after --help; 2 for a bad option, said on stderr). */
int sim_options_parse(int argc, char **argv, sim_options_t *o);
/* A decimal number 0..@p max, the whole of @p text: true with it in *out. */
bool parse_uint(const char *text, unsigned long max, unsigned long *out);

#endif /* SIM_OPTIONS_H */
