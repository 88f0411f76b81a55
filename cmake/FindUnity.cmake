# FindUnity: the Unity C test framework (ThrowTheSwitch), kept outside the
# source tree (tools/fetch-unity puts it there), built as a static library for
# whatever compiler the project uses: host gcc/clang or arm-none-eabi-gcc.
#
# Where, the first one set wins:
#   -DUNITY_ROOT=<dir>, then the environment variable UNITY_ROOT, then
#   ${XDG_CACHE_HOME:-$HOME/.cache}/daran-ascii/unity (tools/fetch-unity's default).
#   <dir> is Unity's top folder: <dir>/src/unity.c, unity.h, unity_internals.h.
# Options:
#   UNITY_CONFIG_HEADER  Unity's options, seen by unity.c and every test file
#                        (default: tests/support/unity_config.h of this project).
#   DARAN_TEST_TARGET    ON: Unity prints through daran_test_putchar() instead of
#                        putchar (default: ON when cross-compiling).
# Results: Unity_FOUND, Unity_VERSION, UNITY_ROOT (cached once found), and the
# target unity::unity (an alias of the static library `unity`).

set(_unity_default_root "$ENV{HOME}/.cache/daran-ascii/unity")
if(NOT "$ENV{XDG_CACHE_HOME}" STREQUAL "")
  set(_unity_default_root "$ENV{XDG_CACHE_HOME}/daran-ascii/unity")
endif()
if(UNITY_ROOT)
  set(_unity_root "${UNITY_ROOT}")
elseif(NOT "$ENV{UNITY_ROOT}" STREQUAL "")
  set(_unity_root "$ENV{UNITY_ROOT}")
else()
  set(_unity_root "${_unity_default_root}")
endif()
get_filename_component(_unity_root "${_unity_root}" ABSOLUTE)

if(NOT EXISTS "${_unity_root}/src/unity.c" OR NOT EXISTS "${_unity_root}/src/unity.h")
  set(Unity_FOUND FALSE)
  set(_unity_env "")
  if(NOT _unity_root STREQUAL _unity_default_root)
    set(_unity_env "UNITY_ROOT=${_unity_root} ")
  endif()
  string(CONCAT _unity_message
      "Unity (the C test framework) is missing: no ${_unity_root}/src/unity.c. "
      "Fetch it once with `${_unity_env}tools/install-deps test` (or only Unity: `${_unity_env}tools/fetch-unity`), "
      "then configure again; a copy elsewhere is taken from -DUNITY_ROOT=<dir> or env UNITY_ROOT.")
  if(Unity_FIND_REQUIRED)
    message(FATAL_ERROR "${_unity_message}")
  elseif(NOT Unity_FIND_QUIETLY)
    message(STATUS "${_unity_message}")
  endif()
  return()
endif()
set(UNITY_ROOT "${_unity_root}" CACHE PATH "Unity's top folder (src/unity.c)" FORCE)

file(STRINGS "${UNITY_ROOT}/src/unity.h" _unity_version_lines
     REGEX "^#define UNITY_VERSION_(MAJOR|MINOR|BUILD) +[0-9]+")
set(Unity_VERSION "")
foreach(_unity_part MAJOR MINOR BUILD)
  string(REGEX MATCH "UNITY_VERSION_${_unity_part} +([0-9]+)" _unity_hit "${_unity_version_lines}")
  if(_unity_hit)
    string(APPEND Unity_VERSION "${CMAKE_MATCH_1}.")
  endif()
endforeach()
string(REGEX REPLACE "\\.$" "" Unity_VERSION "${Unity_VERSION}")
if(Unity_VERSION STREQUAL "" AND EXISTS "${UNITY_ROOT}/release/version.info")
  # Unity before 2.5 states its version only in release/version.info.
  file(STRINGS "${UNITY_ROOT}/release/version.info" _unity_version_lines
       REGEX "^[0-9]+\\.[0-9]+(\\.[0-9]+)?$" LIMIT_COUNT 1)
  set(Unity_VERSION "${_unity_version_lines}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Unity REQUIRED_VARS UNITY_ROOT VERSION_VAR Unity_VERSION)

if(Unity_FOUND AND NOT TARGET unity)
  set(UNITY_CONFIG_HEADER "${CMAKE_CURRENT_LIST_DIR}/../tests/support/unity_config.h"
      CACHE FILEPATH "Unity's options header, included before Unity in unity.c and every test")
  if(CMAKE_CROSSCOMPILING)
    set(_unity_target_default ON)
  else()
    set(_unity_target_default OFF)
  endif()
  option(DARAN_TEST_TARGET "Unity prints through daran_test_putchar() (targets)" ${_unity_target_default})

  add_library(unity STATIC "${UNITY_ROOT}/src/unity.c")
  add_library(unity::unity ALIAS unity)
  # SYSTEM: the tests' own warnings never fire inside Unity's headers and macros.
  target_include_directories(unity SYSTEM PUBLIC "${UNITY_ROOT}/src")
  target_compile_features(unity PUBLIC c_std_99)
  # Third-party code: built with the compiler's defaults, never with -Werror
  # (even when the flags of a preset carry it).
  target_compile_options(unity PRIVATE $<$<C_COMPILER_ID:GNU,Clang>:-Wno-error>)

  if(UNITY_CONFIG_HEADER)
    get_filename_component(_unity_config "${UNITY_CONFIG_HEADER}" ABSOLUTE)
    get_filename_component(_unity_config_dir "${_unity_config}" DIRECTORY)
    # Upstream Unity reads "unity_config.h" under UNITY_INCLUDE_CONFIG_H; the
    # copy in Debian's cjson ignores that and includes its own
    # examples/unity_config.h, so the header is also force-included: every
    # file that uses Unity sees the same options either way.
    target_compile_definitions(unity PUBLIC UNITY_INCLUDE_CONFIG_H)
    target_include_directories(unity PUBLIC "${_unity_config_dir}")
    target_compile_options(unity PUBLIC "SHELL:-include \"${_unity_config}\"")
  endif()
  if(DARAN_TEST_TARGET)
    target_compile_definitions(unity PUBLIC DARAN_TEST_TARGET)
  endif()
endif()
