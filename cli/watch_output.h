/* `daran watch`: where its samples go (watch_output.c): the live view on
 * stdout (a status line redrawn in place on a terminal, a line per sample
 * otherwise, JSON lines with --json), the CSV file, and the data gnuplot
 * draws the PNG from after the run. */
#ifndef DARAN_CLI_WATCH_OUTPUT_H
#define DARAN_CLI_WATCH_OUTPUT_H

#include "cli.h"

/** The telemetry fields of protocol.md 11.2: bit 0..8. */
#define WATCH_FIELDS_MAX 9u
/** Room for one value as the drive prints it (a float takes at most 16
 * characters, a u64 20). */
#define WATCH_TEXT_MAX 32u

/** A field `watch` can show. */
typedef struct watch_field {
    const char *name;     /**< its short name on the command line ("pos") */
    const char *unit;     /**< for the live view and the plot; "" when it has none */
    unsigned bit;         /**< its bit in telemetry.fields, and its place in a report */
    char poll_command;    /**< 'f' or 'g' when polling can read it, else 0 */
    unsigned poll_index;  /**< its place in that reply */
} watch_field_t;

/** One sample: the time and each watched field, as text. */
typedef struct watch_sample {
    char time[WATCH_TEXT_MAX];
    char values[WATCH_FIELDS_MAX][WATCH_TEXT_MAX];
} watch_sample_t;

/** The sinks of one run. Fill the fields marked "set", zero the rest. */
typedef struct watch_output {
    const watch_field_t *fields[WATCH_FIELDS_MAX]; /**< set: what is shown, in order */
    size_t field_count;                             /**< set */
    bool json;                                      /**< set: JSON lines on stdout */
    const char *csv_path;                           /**< set: --csv (NULL: none) */
    const char *plot_path;                          /**< set: --plot (NULL: none) */
    const char *time_label;                         /**< set: the plot's x axis */

    bool terminal;      /**< stdout is a terminal: one line redrawn in place */
    bool opened;        /**< the files are open (at the first sample) */
    FILE *csv;
    FILE *plot_data;
    char plot_data_path[256];
    cli_status_t failed; /**< a file could not be written (reported) */
    bool reader_gone;    /**< stdout cannot be written (`| head` ended): the run is over */
    uint32_t last_draw_ms;
    bool draw_pending;  /**< the newest sample is not on the terminal yet */
    bool line_open;     /**< the status line is on the terminal, not ended */
    watch_sample_t newest;
    unsigned long samples;
} watch_output_t;

/** Whether gnuplot is on PATH (--plot is refused before the run without it). */
bool watch_gnuplot_found(void);

/** Get ready (looks at stdout); nothing is opened before the first sample. */
void watch_output_init(watch_output_t *out);
/** On a terminal, a line saying what is watched (`what`), before the first sample. */
void watch_output_banner(watch_output_t *out, const char *what);
/** Show and record one sample. A file that cannot be written sets
 * out->failed (reported); the caller ends the run. */
void watch_output_sample(watch_output_t *out, const watch_sample_t *sample);
/** Whether the run may go on: no file failed, and stdout still has a reader. */
bool watch_output_going(const watch_output_t *out);
/** On a terminal, end the status line (its newest sample drawn), so that a
 * message or the next line starts on a line of its own. */
void watch_output_end_line(watch_output_t *out);
/** End the run: the last sample drawn, the files closed (the CSV written
 * with its header even when no sample came, if `ok`), and with `ok` the
 * PNG drawn. Returns CLI_OK or the failure it reported. */
cli_status_t watch_output_finish(watch_output_t *out, bool ok);

#endif /* DARAN_CLI_WATCH_OUTPUT_H */
