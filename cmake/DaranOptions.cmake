# Build options shared by every preset, and the strict warning set of the core.
include_guard(GLOBAL)

if(CMAKE_SOURCE_DIR STREQUAL PROJECT_SOURCE_DIR)
  set(_daran_top_level ON)
else()
  set(_daran_top_level OFF)
endif()

option(DARAN_BUILD_TESTS "Build the unit and transcript tests" ${_daran_top_level})
option(DARAN_BUILD_SIM "Build the simulated drive (host only)" ${_daran_top_level})
option(DARAN_BUILD_DEMO "Build the example programs" ${_daran_top_level})
option(DARAN_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
set(DARAN_CONFIG_HEADER "" CACHE STRING "A user options header included by daran_config.h")
set(DARAN_PROPERTY_OMIT "" CACHE STRING "Property ids (DARAN_PROP_<ID> without the prefix) this build leaves out; their paths answer invalid property")

if(DARAN_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# The warnings the core must build clean under, as errors (gcc, clang, arm-none-eabi-gcc).
set(DARAN_STRICT_WARNINGS
    -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wstrict-prototypes
    -Wmissing-prototypes -Wcast-qual -Wundef -Werror)

function(daran_strict_warnings target)
  target_compile_options(${target} PRIVATE ${DARAN_STRICT_WARNINGS})
endfunction()

option(DARAN_BUILD_FUZZ "Build the libFuzzer harnesses (clang only)" OFF)
option(DARAN_BUILD_BENCH "Build the benchmarks" ${_daran_top_level})
option(DARAN_BUILD_FIRMWARE "Cross builds: build the example firmware and its QEMU tests" ${_daran_top_level})
option(DARAN_STACK_USAGE "Write the core's frame sizes and call graph (-fstack-usage -fcallgraph-info, GCC 12+) for a stack budget" OFF)
