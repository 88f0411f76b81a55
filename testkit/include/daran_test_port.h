/* The one entry point an adopter's test-port file provides, so the
 * conformance suite (daran_ascii_add_conformance_test) and the fuzz target
 * (daran_ascii_add_fuzz_target) can run the protocol contract against the
 * adopter's own HAL.
 *
 * A test-port file is plain C compiled against the adopter's core (its
 * options header). It defines daran_test_port() and nothing else the
 * programs need. Host only: the programs use stdio. */
#ifndef DARAN_TEST_PORT_H
#define DARAN_TEST_PORT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_ascii.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What the adopter hands over. */
typedef struct daran_test_port {
    /** The port's name, printed in reports ("acme-x2 rev B"). */
    const char *name;
    /** The port's description (daran_hal_t) and its context, as the
     * firmware gives them to daran_init(): get, set, move and action; for
     * CAN (docs/can.md) now_ms and can_send, and can_system if the port
     * has one. Its write and forward are not used: the programs collect
     * the replies themselves. The programs wrap it in a recording shim
     * (daran_recorder.h); the HAL never sees the shim. */
    const daran_hal_t *hal;
    void *ctx;

    /** Put the drive in its factory state: non-volatile memory erased,
     * defaults loaded, no error flag, closed loop (motion accepted), node id
     * 1. Called before every check. Return false when it could not. */
    bool (*reset)(void *ctx);

    /** Optional (NULL: none): let @p ms milliseconds of drive time pass, so
     * a move or a save can complete. */
    void (*advance)(void *ctx, uint32_t ms);

    /** Optional (NULL / 0: none): the port's own command table, given to
     * daran_set_port_commands() after daran_init(); the handlers get
     * @ref ctx, as on the firmware's drive. */
    const daran_port_command_t *commands;
    size_t command_count;

    /** Optional, CAN only (NULL: frames go to daran_can_receive() directly
     * and the filter requirement is skipped): give @p frame to the drive as
     * the bus would, through the port's acceptance filter and receive path
     * into daran_can_receive(@p can, @p frame). Without hal->can_send and
     * hal->now_ms the CAN requirements are reported as skipped and the CAN
     * fuzz target refuses to run. The suite owns the daran_can_t; it wraps
     * can_send to see every frame the drive sends, then hands the frame on
     * (a false answer is reported); now_ms must be the drive time that
     * advance() lets pass. */
    void (*can_deliver)(void *ctx, daran_can_t *can, const daran_can_frame_t *frame);
} daran_test_port_t;

/** Defined by the adopter's test-port file; called once per program run.
 * The returned object must outlive the program. */
const daran_test_port_t *daran_test_port(void);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_TEST_PORT_H */
