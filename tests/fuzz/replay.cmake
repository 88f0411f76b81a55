# The fuzz harnesses built standalone (replay_main.c instead of libFuzzer) in
# the normal test build, so CTest replays the corpus and every past finding
# under gcc (or clang) with the sanitizers of the preset, plus the HAL
# fault-injection test. Included from tests/CMakeLists.txt.
set(_fz ${CMAKE_CURRENT_LIST_DIR})
set(_corpus ${PROJECT_SOURCE_DIR}/tests/corpus)

# fuzz_port replays on the core compiled with the example port's options
# header (port_core.cmake), with the example's command table.
include(${_fz}/port_core.cmake)
daran_port_core(daran_ascii_port_replay)

foreach(h stream line number sim telemetry port can bridge)
  if(h STREQUAL "sim" AND NOT TARGET daran_sim_model)
    continue()
  endif()
  add_executable(fuzz_replay_${h} ${_fz}/fuzz_${h}.c ${_fz}/fuzz_hal.c ${_fz}/replay_main.c)
  target_include_directories(fuzz_replay_${h} PRIVATE ${DARAN_CORE_INTERNAL_INCLUDES} ${_fz}
    ${PROJECT_SOURCE_DIR}/tests/support)
  target_compile_options(fuzz_replay_${h} PRIVATE -Wall -Wextra)
  if(h STREQUAL "port")
    target_sources(fuzz_replay_${h} PRIVATE ${DARAN_PORT_EXAMPLE_DIR}/brake_port.c)
    target_include_directories(fuzz_replay_${h} PRIVATE ${DARAN_PORT_EXAMPLE_DIR})
    target_link_libraries(fuzz_replay_${h} PRIVATE daran_ascii_port_replay m)
  else()
    target_link_libraries(fuzz_replay_${h} PRIVATE daran_ascii m)
  endif()
  if(h STREQUAL "sim")
    target_link_libraries(fuzz_replay_${h} PRIVATE daran_sim_model)
  endif()
  add_test(NAME fuzz_corpus_${h} COMMAND fuzz_replay_${h} ${_corpus}/${h})
  # One named test per past finding: regression_<harness>_<what it guards>.
  file(GLOB _regressions ${_corpus}/regressions/${h}/*)
  foreach(r IN LISTS _regressions)
    get_filename_component(_name ${r} NAME_WE)
    add_test(NAME regression_${h}_${_name} COMMAND fuzz_replay_${h} ${r})
  endforeach()
endforeach()

# The only program here that links Unity: the harnesses and fuzz_hal.c need
# nothing but the core.
daran_add_unity_test(test_hal_fault_injection ${_fz}/test_hal_fault_injection.c ${_fz}/fuzz_hal.c)
target_include_directories(test_hal_fault_injection PRIVATE ${_fz})
target_link_libraries(test_hal_fault_injection PRIVATE m)
