# Build options shared by every preset, and the strict warning set of the core.
include_guard(GLOBAL)

if(CMAKE_SOURCE_DIR STREQUAL PROJECT_SOURCE_DIR)
  set(_daran_top_level ON)
else()
  set(_daran_top_level OFF)
endif()

option(DARAN_BUILD_TESTS "Build the unit and transcript tests" ${_daran_top_level})
option(DARAN_BUILD_SIM "Build the simulated drive (host only)" ${_daran_top_level})
option(DARAN_BUILD_CLI "Build daran, the command-line tool (host only; needs libedit-dev)" ${_daran_top_level})
option(DARAN_BUILD_DEMO "Build the example programs" ${_daran_top_level})
option(DARAN_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
# A project that pulls the library in with add_subdirectory() may name its
# header with a plain set() before it (docs/porting.md 5.1). Under policy
# CMP0126 OLD (any project requiring CMake < 3.21) declaring the cache entry
# would drop that normal variable and build with the vendor defaults, so the
# entry takes the variable's value and the NEW behaviour is asked for where
# CMake knows it.
if(POLICY CMP0126)
  cmake_policy(SET CMP0126 NEW)
endif()
set(DARAN_CONFIG_HEADER "${DARAN_CONFIG_HEADER}" CACHE STRING
    "A user options header included by daran_config.h (absolute, or relative to the top-level source folder)")
# A relative header names a file of the project being configured: the
# top-level source folder (CMAKE_SOURCE_DIR: this tree for its own presets, the
# consumer's for a project that adds this tree with add_subdirectory()), not
# the folder that happens to use it (src/, tests/...). The absolute path, as a
# normal variable of this tree's scope, is what every folder below sees.
if(DARAN_CONFIG_HEADER)
  get_filename_component(_daran_config_header "${DARAN_CONFIG_HEADER}" ABSOLUTE
                         BASE_DIR "${CMAKE_SOURCE_DIR}")
  if(NOT EXISTS "${_daran_config_header}")
    message(FATAL_ERROR "DARAN_CONFIG_HEADER: ${DARAN_CONFIG_HEADER} not found (looked for "
                        "${_daran_config_header}; give an absolute path, or one relative to "
                        "the top-level source folder ${CMAKE_SOURCE_DIR})")
  endif()
  set(DARAN_CONFIG_HEADER "${_daran_config_header}")
endif()
set(DARAN_PROPERTY_OMIT "${DARAN_PROPERTY_OMIT}" CACHE STRING "Property ids (DARAN_PROP_<ID> without the prefix) this build leaves out; their paths answer invalid property")

if(DARAN_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# DARAN_STRICT_WARNINGS and daran_ascii_add_library(); the package's root
# for the functions that compile its sources (here: this source tree).
include(DaranAddLibrary)
daran_ascii_set_root("${PROJECT_SOURCE_DIR}" "${PROJECT_SOURCE_DIR}/include")
# The core's internal folders, for this tree's tests, client and benchmarks.
daran_core_include_dirs(DARAN_CORE_INTERNAL_INCLUDES)
# The package's other functions, defined whether or not this build makes the
# simulator or the test kit itself (a project that adds this tree with
# add_subdirectory() calls them for its own core).
include(DaranSim)
include(DaranTestSupport)
include(DaranConformance)
include(DaranFuzzTarget)
set(DARAN_CORE_C_STANDARD 11 CACHE STRING "C standard the core is compiled with (99 or 11)")

function(daran_strict_warnings target)
  daran_ascii_strict_warnings(${target})
endfunction()

option(DARAN_BUILD_FUZZ "Build the libFuzzer harnesses (clang only)" OFF)
option(DARAN_BUILD_BENCH "Build the benchmarks" ${_daran_top_level})
option(DARAN_BUILD_FIRMWARE "Cross builds: build the example firmware and its QEMU tests" ${_daran_top_level})
option(DARAN_STACK_USAGE "Write the core's frame sizes and call graph (-fstack-usage -fcallgraph-info, GCC 12+) for a stack budget" OFF)

# Install rules (cmake/DaranInstall.cmake and each folder's own): a project
# that pulls daran-ascii in with add_subdirectory() usually does not want our
# files in its own install tree.
option(DARAN_INSTALL "Generate the install rules of daran-ascii" ${_daran_top_level})
include(GNUInstallDirs)
set(DARAN_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/daran_ascii"
    CACHE STRING "Where the CMake package files go, relative to the prefix")
mark_as_advanced(DARAN_INSTALL_CMAKEDIR)
# The sources an adopter compiles for their own options (the core, the
# generator, the simulated drive, the test kit), in the source tree's layout.
set(DARAN_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/daran_ascii")
