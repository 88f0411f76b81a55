# daran_ascii_add_library(<target> [CONFIG_HEADER <file>] [OMIT <id>...])
#
# The protocol core compiled for one options header: the library's sources
# (the source tree through add_subdirectory, <prefix>/share/daran_ascii from an
# installed package) and a property index generated from the vendor's list,
# the header's DARAN_PORT_PROPERTY_LIST and DARAN_OMIT_PROPERTIES, less the
# OMIT ids. The generator runs while the project configures, so a refused
# header (a path twice, a vendor id reused, a bad range, an error register
# left out) stops the configure with a message naming the header and the row;
# CMake configures again when the header changes.
#
# Linking <target> gives the public headers and DARAN_CONFIG_HEADER, so every
# program compiled against it sees the same options (daran_init() refuses a
# mismatch, see daran_drive.h). The same function builds the library's own
# default daran_ascii (src/CMakeLists.txt).
include_guard(GLOBAL)

# The warnings the core must build clean under, as errors (gcc, clang, arm-none-eabi-gcc).
set(DARAN_STRICT_WARNINGS
    -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wstrict-prototypes
    -Wmissing-prototypes -Wcast-qual -Wundef -Werror)

# One stage a file, in a folder a room (docs/design.md): the link (ring,
# framer, checksum), the ASCII front end, the request layer over the HAL
# door, CAN (front end, codec, bridge), text and numbers, the property
# table. A global property, as the functions below run in their callers'
# directory scopes.
set_property(GLOBAL PROPERTY DARAN_CORE_ROOMS link ascii request can update text table)
set_property(GLOBAL PROPERTY DARAN_CORE_SOURCES
  link/rx_ring.c link/framer.c link/checksum.c
  ascii/drive.c ascii/command_table.c ascii/commands_common.c ascii/commands_motion.c
  ascii/commands_multi.c ascii/commands_property.c ascii/commands_query.c
  ascii/commands_system.c ascii/discovery.c ascii/port_commands.c ascii/telemetry.c
  ascii/reply.c
  request/request_preset.c request/request_property.c request/request_state.c request/hal.c
  request/hal_can.c
  update/update.c update/hash.c
  can/can.c can/can_address.c can/can_bridge.c can/can_codec.c can/can_encode.c can/can_ring.c
  text/number.c text/text.c text/result.c
  table/property_table.c
  version.c)
set_property(GLOBAL PROPERTY DARAN_STRICT_WARNINGS ${DARAN_STRICT_WARNINGS})

# daran_core_include_dirs(<out>): the core's own folders (src and each
# room), for what includes its internal headers (the library, its tests,
# the client, the benchmarks).
function(daran_core_include_dirs out)
  get_property(_root GLOBAL PROPERTY DARAN_ASCII_ROOT)
  get_property(_rooms GLOBAL PROPERTY DARAN_CORE_ROOMS)
  set(_dirs "${_root}/src")
  foreach(_room IN LISTS _rooms)
    list(APPEND _dirs "${_root}/src/${_room}")
  endforeach()
  set(${out} ${_dirs} PARENT_SCOPE)
endfunction()

# Compile <target> with the core's warning set, as errors.
function(daran_ascii_strict_warnings target)
  get_property(_warnings GLOBAL PROPERTY DARAN_STRICT_WARNINGS)
  target_compile_options(${target} PRIVATE ${_warnings})
endfunction()

# The package's root (the layout of the source tree) and public include folder,
# for functions called from any directory scope: set by the top-level
# CMakeLists.txt, or by daran_asciiConfig.cmake for an installed package.
function(daran_ascii_set_root root include_dir)
  set_property(GLOBAL PROPERTY DARAN_ASCII_ROOT "${root}")
  set_property(GLOBAL PROPERTY DARAN_ASCII_INCLUDE_DIR "${include_dir}")
endfunction()

# The helpers of the package's functions (this module, DaranSim,
# DaranTestSupport, DaranConformance, DaranFuzzTarget), each named by the
# function that calls it in its messages:
#
# _daran_package_dir(<out> <caller> <folder> <file>...): <out> is <folder>
# of the package (the source tree's layout under DARAN_ASCII_ROOT; "" for the
# root itself), after checking that each <file> is there.
function(_daran_package_dir out caller folder)
  get_property(_root GLOBAL PROPERTY DARAN_ASCII_ROOT)
  set(_dir "${_root}")
  if(folder)
    set(_dir "${_root}/${folder}")
  endif()
  foreach(_file IN LISTS ARGN)
    if(NOT _root OR NOT EXISTS "${_dir}/${_file}")
      message(FATAL_ERROR "${caller}: '${_dir}/${_file}' is missing: the package's sources are "
                          "not under DARAN_ASCII_ROOT ('${_root}'); install daran-ascii with them "
                          "(its default) or use it through add_subdirectory")
    endif()
  endforeach()
  set(${out} "${_dir}" PARENT_SCOPE)
endfunction()

# _daran_check_core(<caller> <library>): stop unless <library> is a core target.
function(_daran_check_core caller library)
  if(NOT library)
    message(FATAL_ERROR "${caller}: LIBRARY <core target> is required (a target of "
                        "daran_ascii_add_library(), or daran_ascii::daran_ascii)")
  endif()
  if(NOT TARGET ${library})
    message(FATAL_ERROR "${caller}: LIBRARY ${library} is not a target")
  endif()
endfunction()

# _daran_check_flags(<result> <source> <flag>...): does the compiler compile
# and link <source> with the flags? Cached in <result>.
function(_daran_check_flags result source)
  if(DEFINED ${result})
    return()
  endif()
  include(CheckCSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "${ARGN}")
  string(REPLACE ";" " " CMAKE_REQUIRED_FLAGS "${CMAKE_REQUIRED_FLAGS}")
  set(CMAKE_REQUIRED_LINK_OPTIONS ${ARGN})
  set(CMAKE_REQUIRED_QUIET ON)
  check_c_source_compiles("${source}" ${result})
endfunction()

# A 32-bit signature of an OMIT list, for daran_init()'s build check: the
# list reaches the generator only, so the programs compiled against the core
# learn it through this definition (DARAN_OMIT_LIST_SIGNATURE).
function(_daran_omit_signature out)
  list(SORT ARGN)
  list(REMOVE_DUPLICATES ARGN)
  if(NOT ARGN)
    set(${out} 0 PARENT_SCOPE)
    return()
  endif()
  string(SHA256 _hash "${ARGN}")
  string(SUBSTRING "${_hash}" 0 8 _hash)
  set(${out} "0x${_hash}u" PARENT_SCOPE)
endfunction()

function(daran_ascii_add_library target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "CONFIG_HEADER" "OMIT")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "daran_ascii_add_library(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  _daran_package_dir(_root "daran_ascii_add_library(${target})" "" src/ascii/drive.c
                     tools/gen_property_index.py)
  get_property(_include GLOBAL PROPERTY DARAN_ASCII_INCLUDE_DIR)

  set(_header "")
  set(_config_args "")
  if(arg_CONFIG_HEADER)
    get_filename_component(_header "${arg_CONFIG_HEADER}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    if(NOT EXISTS "${_header}")
      message(FATAL_ERROR "daran_ascii_add_library(${target}): CONFIG_HEADER ${arg_CONFIG_HEADER} "
                          "not found (looked for ${_header})")
    endif()
    set(_config_args --config "${_header}")
  endif()
  string(REPLACE ";" "," _omit "${arg_OMIT}")

  find_package(Python3 COMPONENTS Interpreter REQUIRED)
  set(_generator "${_root}/tools/gen_property_index.py")
  set(_list "${_include}/daran_properties.h")
  set(_gen_dir "${CMAKE_CURRENT_BINARY_DIR}/${target}_generated")
  file(MAKE_DIRECTORY "${_gen_dir}")
  execute_process(
    COMMAND "${Python3_EXECUTABLE}" "${_generator}" --list "${_list}" ${_config_args}
            --omit "${_omit}" --out "${_gen_dir}/property_index.h"
    RESULT_VARIABLE _status
    ERROR_VARIABLE _error
    OUTPUT_VARIABLE _output)
  if(NOT _status EQUAL 0)
    string(STRIP "${_error}${_output}" _error)
    message(FATAL_ERROR "daran_ascii_add_library(${target}): the property table was refused:\n"
                        "  ${_error}")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_generator}" "${_list}" ${_header})

  set(_sources "${_gen_dir}/property_index.h")
  get_property(_core_sources GLOBAL PROPERTY DARAN_CORE_SOURCES)
  foreach(_source IN LISTS _core_sources)
    list(APPEND _sources "${_root}/src/${_source}")
  endforeach()
  add_library(${target} STATIC ${_sources})
  daran_core_include_dirs(_rooms)
  target_include_directories(${target} PRIVATE "${_gen_dir}" ${_rooms})
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${_include}>")
  target_compile_features(${target} PUBLIC c_std_99)
  # Built as C11 for <stdatomic.h> (the receive ring's acquire/release); the
  # code and the headers stay C99, and callers may be C99.
  if(NOT DEFINED DARAN_CORE_C_STANDARD)
    set(DARAN_CORE_C_STANDARD 11)
  endif()
  set_target_properties(${target} PROPERTIES C_STANDARD ${DARAN_CORE_C_STANDARD}
                        C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  # sqrtf must become one instruction (vsqrt.f32 / sqrtss), never a libm call that sets errno.
  target_compile_options(${target} PRIVATE -fno-math-errno)
  # gcc turns zeroing and copying loops into memset/memcpy calls: library code
  # outside the core's measured flash and stack, and slow for a few words.
  target_compile_options(${target} PRIVATE
    $<$<C_COMPILER_ID:GNU>:-fno-tree-loop-distribute-patterns>)
  daran_ascii_strict_warnings(${target})
  if(_header)
    target_compile_definitions(${target} PUBLIC "$<BUILD_INTERFACE:DARAN_CONFIG_HEADER=${_header}>")
  endif()
  _daran_omit_signature(_omit_signature ${arg_OMIT})
  if(NOT _omit_signature STREQUAL "0")
    target_compile_definitions(${target} PUBLIC DARAN_OMIT_LIST_SIGNATURE=${_omit_signature})
  endif()
  # Hosts where sqrtf is not inlined (gcc -O0) take it from libm.
  if(NOT CMAKE_CROSSCOMPILING)
    find_library(DARAN_LIBM m)
    if(DARAN_LIBM)
      target_link_libraries(${target} PUBLIC m)
    endif()
  endif()
endfunction()
