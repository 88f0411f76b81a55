# The conformance suite's sources, relative to this folder: read by
# daran_ascii_add_conformance_test() (cmake/DaranConformance.cmake) and by the
# install rules (testkit/CMakeLists.txt).
set(DARAN_CONFORMANCE_SOURCES
  main.c
  harness.c
  model.c
  check_properties.c
  check_commands.c
  check_persistence.c
  check_bad_input.c
  can_harness.c
  check_can.c)
set(DARAN_CONFORMANCE_HEADERS conformance.h)
