/** @file daran_sim.h
 * The simulated Daran drive as a library (daran_ascii::sim): the physical
 * model of daran-sim (a motor and its load under a cascaded controller,
 * trajectories, temperatures, bus voltage, protections, error registers),
 * its non-volatile memory, fault injection and the multi-drop bus, behind
 * the protocol core's HAL. A host test runs the firmware's protocol layer
 * (daran_drive_t, the port's own commands) against it:
 *
 *     static daran_sim_drive_t sim;
 *     static daran_drive_t drive;
 *     static const daran_hal_t hal = {DARAN_SIM_HAL_FUNCTIONS, .write = write_reply};
 *     daran_sim_drive_init(&sim, 0u, 1000u);            // drive id 1, 1 kHz ticks
 *     daran_init(&drive, &hal, &sim);                   // write_reply gets &sim
 *     daran_process_line(&drive, "q 1 90", 6);          // a trapezoid to 90 deg
 *     for (int i = 0; i < 2000; i++) daran_sim_drive_tick(&sim);   // 2 s
 *
 * The parts (each header documents its functions):
 *   sim_model.h      the plant and controller, every property of the table;
 *                    a port's own rows (DARAN_PORT_PROPERTY_LIST) kept in a
 *                    plain store (daran_sim_is_port_prop())
 *   sim_nvm.h        the two-slot configuration store behind `ss`/`se`/boot
 *   sim_drive.h      one drive: model + NVM + identity, and its HAL functions
 *   sim_extension.h  the test's own properties layered over the model
 *   sim_faults.h     stall, overspeed, overtemp, undervoltage, nvm-corrupt;
 *                    HAL refusals; failing NVM saves
 *   sim_bus.h        N drives on one line, each with its protocol instance
 *   sim_can_bus.h    a CAN bus: queues, arbitration, frame timing, bus faults
 *   sim_can.h        the line's drives on a CAN bus, each with its CAN front
 *                    end (daran_can_t)
 *
 * Conventions: functions that can fail return daran_result_t (DARAN_OK is
 * 0; DARAN_ERR_BAD_ARGUMENT reports misuse; any other value is the error
 * the drive answers), or bool where noted; the caller owns every object (no
 * heap; sizes are those of the structs); nothing here is thread-safe: call
 * a drive's functions from the thread that runs its protocol instance.
 * Units are the protocol's (degrees, r/min, Nm, seconds at the output
 * shaft). The library is compiled per core target (the property table of
 * the options header decides daran_value_t cfg[DARAN_PROP_COUNT]): the
 * prebuilt daran_ascii::sim for daran_ascii::daran_ascii, and
 * daran_ascii_add_sim(<target> LIBRARY <core>) for a port's own core.
 * docs/simulator.md ("The simulated drive as a library") has the details. */
#ifndef DARAN_SIM_H
#define DARAN_SIM_H

#include "daran_ascii.h"
#include "sim_bus.h"
#include "sim_can.h"
#include "sim_can_bus.h"
#include "sim_drive.h"
#include "sim_extension.h"
#include "sim_faults.h"
#include "sim_model.h"
#include "sim_nvm.h"

#endif /* DARAN_SIM_H */
