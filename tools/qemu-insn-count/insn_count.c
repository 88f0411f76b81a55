/* QEMU TCG plugin: count guest instructions between executions of one
 * marker address, for per-line instruction counts of the firmware.
 *
 *   qemu-system-arm ... -plugin ./libinsn_count.so,mark=0xADDR
 *
 * Every time the translation block at ADDR (a marker function's entry)
 * runs, the count since the previous marker is printed as "mark N COUNT".
 * With profile=K as well, the instructions of the interval printed as
 * "mark K" are also printed per translation block as "block ADDR COUNT",
 * for a per-function breakdown (tools/qemu-insn-count/measure_insns.py).
 * Counting is per translation block (inline add at block entry), exact as
 * long as no exception leaves a block part-way; the measured image runs
 * with interrupts off between markers.
 *
 * Debian's QEMU 7.2 ships no plugin header, so the few API declarations this
 * plugin uses are written out here. They match plugin API version 1, which
 * QEMU 5.0 .. 8.1 accept. */
#include <inttypes.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLUGIN_EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
typedef struct qemu_info_t qemu_info_t; /* only passed through */

enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb *tb, qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
void qemu_plugin_outs(const char *string);

PLUGIN_EXPORT int qemu_plugin_version = 1;
PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
                                      char **argv);

static uint64_t executed;   /* instructions so far (single vCPU) */
static uint64_t at_last_mark;
static uint64_t mark_addr = UINT64_MAX;
static unsigned long marks;

#define PROFILE_SLOTS 4096u
static long profile_interval = -1;
static struct {
    uint64_t addr;
    uint64_t count;
} profile[PROFILE_SLOTS];

static void on_block(unsigned int vcpu, void *udata)
{
    uint64_t addr = (uint64_t)(uintptr_t)udata >> 16;
    uint64_t n = (uint64_t)(uintptr_t)udata & 0xFFFFu;
    uint32_t slot = (uint32_t)(addr * 2654435761u) % PROFILE_SLOTS;
    (void)vcpu;
    if ((long)marks != profile_interval) {
        return;
    }
    for (uint32_t probe = 0; probe < PROFILE_SLOTS; probe++) {
        uint32_t i = (slot + probe) % PROFILE_SLOTS;
        if (profile[i].count == 0u || profile[i].addr == addr) {
            profile[i].addr = addr;
            profile[i].count += n;
            return;
        }
    }
}

static void on_mark(unsigned int vcpu, void *udata)
{
    char line[64];
    (void)vcpu;
    (void)udata;
    /* Whether the marker block's own instructions land before or after this
     * point is the same every time: a constant the caller measures with an
     * empty interval and subtracts. */
    snprintf(line, sizeof line, "mark %lu %" PRIu64 "\n", marks++, executed - at_last_mark);
    qemu_plugin_outs(line);
    at_last_mark = executed;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    if (qemu_plugin_tb_vaddr(tb) == mark_addr) {
        qemu_plugin_register_vcpu_tb_exec_cb(tb, on_mark, QEMU_PLUGIN_CB_NO_REGS, NULL);
    }
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &executed,
                                             qemu_plugin_tb_n_insns(tb));
    if (profile_interval >= 0) {
        /* address and length packed in the user pointer: no allocation */
        uintptr_t packed = (uintptr_t)(qemu_plugin_tb_vaddr(tb) << 16) |
                           (uintptr_t)(qemu_plugin_tb_n_insns(tb) & 0xFFFFu);
        qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS,
                                             (void *)packed);
    }
}

static void report_total(qemu_plugin_id_t id, void *udata)
{
    char line[64];
    (void)id;
    (void)udata;
    for (uint32_t i = 0; i < PROFILE_SLOTS; i++) {
        if (profile[i].count != 0u) {
            snprintf(line, sizeof line, "block 0x%" PRIx64 " %" PRIu64 "\n", profile[i].addr,
                     profile[i].count);
            qemu_plugin_outs(line);
        }
    }
    snprintf(line, sizeof line, "total %" PRIu64 "\n", executed);
    qemu_plugin_outs(line);
}

int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv)
{
    (void)info;
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "mark=", 5) == 0) {
            mark_addr = strtoull(argv[i] + 5, NULL, 0) & ~(uint64_t)1; /* Thumb bit */
        } else if (strncmp(argv[i], "profile=", 8) == 0) {
            profile_interval = strtol(argv[i] + 8, NULL, 0);
        }
    }
    if (mark_addr == UINT64_MAX) {
        qemu_plugin_outs("insn_count: mark=ADDR is required\n");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, report_total, NULL);
    return 0;
}
