/* Fault injection for tests: the physical faults of the model and the NVM
 * (daran-sim's `!fault` directive goes through these), a HAL that refuses
 * its next calls, an NVM whose next saves fail.
 *
 * Every function here is O(1) (the name lookups O(number of faults)), works
 * on one drive and has its effect at once (the physical faults at the next
 * control tick, daran_sim_drive_tick()). Portable C99: no stdio, no heap. */
#ifndef DARAN_SIM_FAULTS_H
#define DARAN_SIM_FAULTS_H

#include <stdbool.h>
#include <stdint.h>

#include "sim_drive.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The fault names of `!fault ID KIND`, as daran-sim lists them. */
#define DARAN_SIM_FAULT_NAMES "overtemp, undervoltage, stall, overspeed, nvm-corrupt"

/* Inject @p fault into drive @p d. What each does, and what the drive then
 * answers (docs/simulator.md, "Fault injection"):
 *   DARAN_SIM_FAULT_OVERTEMP      temperatures jump above their upper limits;
 *                                 enabled thermistors trip at the next tick
 *                                 (idle, axis0.error 0x40000)
 *   DARAN_SIM_FAULT_UNDERVOLTAGE  the bus sags to 2 V below the trip level for
 *                                 0.1 s from the next tick, which the tick after
 *                                 sees: it trips (idle, axis0.error 0x2)
 *   DARAN_SIM_FAULT_STALL         the next tick trips the stall limiter (idle,
 *                                 motor.error 0x10000, axis0.error 0x40)
 *   DARAN_SIM_FAULT_OVERSPEED     the shaft is thrown beyond vel_limit x
 *                                 vel_limit_tolerance; with enable_overspeed_error
 *                                 the next tick in closed loop trips (idle,
 *                                 controller.error 0x1, axis0.error 0x200)
 *   DARAN_SIM_FAULT_NVM_CORRUPT   the stored config is damaged; the next boot
 *                                 loads the defaults and raises config_warnings
 *                                 bit 0
 * After a trip, motion commands answer `error: motor fault` until `sc`.
 * Returns DARAN_OK; DARAN_ERR_MOTOR_FAULT when the storage failed while
 * damaging it; DARAN_ERR_BAD_ARGUMENT for a value outside the enum. */
DARAN_NODISCARD daran_result_t daran_sim_drive_inject_fault(daran_sim_drive_t *d,
                                                            daran_sim_fault_t fault);

/* The fault named @p name ("overtemp", "undervoltage", "stall", "overspeed",
 * "nvm-corrupt"): true with it in *fault; false (nothing written) for any
 * other text. */
bool daran_sim_fault_from_name(const char *name, daran_sim_fault_t *fault);

/* The name of @p fault (as above); NULL for a value outside the enum. */
const char *daran_sim_fault_name(daran_sim_fault_t fault);

/* A HAL refusal: the next @p count calls of kind @p call (any property,
 * move or action) answer @p result and change nothing; the drive replies
 * `error: <phrase of result>` where the core passes a HAL error on (a `w`,
 * a motion command, `ss`...). A getter refused while the core checks a line
 * (the drive's id or state) makes that line fail too. @p count 0 cancels a
 * pending refusal. Replaces what was pending for that kind.
 * DARAN_ERR_BAD_ARGUMENT (nothing armed) when @p call is not a kind or
 * @p result is not a protocol error (DARAN_OK, DARAN_ERR_BAD_ARGUMENT and
 * the results after it, which are never sent on the link). */
DARAN_NODISCARD daran_result_t daran_sim_drive_refuse_calls(daran_sim_drive_t *d,
                                                            daran_sim_hal_call_t call,
                                                            uint32_t count,
                                                            daran_result_t result);

/* How many refusals of kind @p call are still pending (0 for a bad kind). */
uint32_t daran_sim_drive_refusals_left(const daran_sim_drive_t *d, daran_sim_hal_call_t call);

/* A failing NVM write: the next @p count saves (`ss`) answer `error: motor
 * fault` and write nothing, so the stored config (what the next boot loads)
 * stays as it was. 0 cancels. */
void daran_sim_drive_fail_nvm_saves(daran_sim_drive_t *d, uint32_t count);

/* Cancel every pending refusal and failing save (the physical faults are
 * the model's state: `sc` and the physics clear them). */
void daran_sim_drive_clear_injections(daran_sim_drive_t *d);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_SIM_FAULTS_H */
