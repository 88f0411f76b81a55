/* daran-sim's --nvm files (sim_nvm_dir.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "sim_nvm_dir.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "sim_app.h"
#include "sim_diag.h"

/* With --nvm the shaft angles persist too (DIR/drive-K.shaft): the shaft
 * does not turn while the program is not running, so a zero set with `sz`
 * and saved still reads 0 after a restart. */
static void shaft_file(char *path, size_t size, const char *dir, uint32_t index)
{
    snprintf(path, size, "%s/drive-%u.shaft", dir, index + 1u);
}

void load_shafts(const char *dir)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        FILE *f;
        float angle;
        shaft_file(path, sizeof path, dir, i);
        f = fopen(path, "r");
        if (f == NULL) {
            if (errno != ENOENT) {
                diag_msg("--nvm: cannot read %s (%s): the shaft starts at 0 deg", path,
                         strerror(errno));
            }
            continue;
        }
        if (fscanf(f, "%f", &angle) == 1 && isfinite(angle)) {
            app.bus.node[i].sim.model.raw_pos_deg = angle;
            daran_sim_bus_power_cycle(&app.bus, i);
        } else {
            diag_msg("--nvm: %s holds no shaft angle: the shaft starts at 0 deg", path);
        }
        fclose(f);
    }
}

/* Each file is replaced whole: written beside it, then renamed over it, so
 * whenever the program stops (a signal, a kill) a shaft file holds the old
 * angle or the new one, never a part. False (and said on stderr) when one
 * could not be written. */
bool save_shafts(const char *dir)
{
    bool ok = true;
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        char tmp[4200];
        FILE *f;
        int err = 0;
        shaft_file(path, sizeof path, dir, i);
        snprintf(tmp, sizeof tmp, "%s.tmp", path);
        f = fopen(tmp, "w");
        if (f == NULL) {
            err = errno;
        } else {
            if (fprintf(f, "%.9g\n", (double)app.bus.node[i].sim.model.raw_pos_deg) < 0 ||
                fflush(f) != 0) {
                err = errno != 0 ? errno : EIO;
            }
            if (fclose(f) != 0 && err == 0) {
                err = errno;
            }
            if (err == 0 && rename(tmp, path) != 0) {
                err = errno;
            }
            if (err != 0) {
                (void)unlink(tmp);
            }
        }
        if (err != 0) {
            diag_urgent("--nvm: cannot write %s: %s", path, strerror(err));
            ok = false;
        }
    }
    return ok;
}

int open_nvm(const char *dir)
{
    uint32_t i;
    for (i = 0; i < app.bus.count; i++) {
        char path[4096];
        daran_sim_storage_t st;
        int n = snprintf(path, sizeof path, "%s/drive-%u.nvm", dir, i + 1u);
        if (n < 0 || (size_t)n >= sizeof path) {
            fprintf(stderr, "daran-sim: --nvm path too long\n");
            return 2;
        }
        if (!daran_sim_file_storage_open(&app.files[i], path, &st)) {
            fprintf(stderr, "daran-sim: --nvm: cannot open %s: %s\n", path, strerror(errno));
            return 2;
        }
        daran_sim_bus_set_storage(&app.bus, i, &st);
        if (app.bus.node[i].sim.nvm_status == DARAN_SIM_NVM_DAMAGED) {
            diag_msg("--nvm: %s is damaged or holds a value out of range: drive %u boots on "
                     "defaults (axis0.config_warnings bit 0)",
                     path, i + 1u);
        }
    }
    return 0;
}
