# The simulated drive library (daran_sim.h): its sources and public headers,
# relative to this folder. Read by port/sim/lib/CMakeLists.txt and by
# daran_ascii_add_sim() (cmake/DaranSim.cmake), in the source tree and from
# <prefix>/share/daran_ascii/port/sim/lib where the package installs this
# folder. daran-sim's own files are in ../program, not part of it.
set(DARAN_SIM_LIBRARY_SOURCES
  sim_model.c
  sim_nvm.c
  sim_drive.c
  sim_bus.c
  sim_can_bus.c
  sim_can.c
  sim_extension.c
  sim_faults.c)
set(DARAN_SIM_LIBRARY_HEADERS
  daran_sim.h
  sim_model.h
  sim_nvm.h
  sim_drive.h
  sim_bus.h
  sim_can_bus.h
  sim_can.h
  sim_extension.h
  sim_faults.h)
