# daran_ascii_add_fuzz_target(<name> LIBRARY <core target> SOURCES <file>...
#                             [INCLUDE_DIRECTORIES <dir>...]
#                             [CORPUS <dir or recording>...] [SECONDS <n>] [TIMEOUT <s>])
#
# Fuzzes an adopter's port: the protocol core of <core target> (made by
# daran_ascii_add_library()) driving the HAL that the adopter's test-port file
# hands over with daran_test_port() (testkit/include/daran_test_port.h).
# SOURCES are that file and the HAL's sources (not a library of them: the HAL
# is compiled with the harness's instrumentation), INCLUDE_DIRECTORIES the
# folders their headers are in. testkit/fuzz/README.md says what is checked.
#
# It makes, with any compiler:
#   <name>_replay   runs stored inputs through the harness without libFuzzer;
#                   CTest runs it over CORPUS as the test <name>_replay.
# and, when the compiler is clang and links -fsanitize=fuzzer:
#   <name>          the libFuzzer harness (libFuzzer + ASan + UBSan);
#   <name>_seeds    (built by default) the seeds of the CORPUS recordings as
#                   libFuzzer inputs, in <build dir>/<name>_seeds/;
#   <name>_run      (on demand: cmake --build <dir> --target <name>_run) fuzzes
#                   SECONDS seconds (default 20) from the seeds and the CORPUS
#                   directories, new inputs in <build dir>/<name>_corpus/,
#                   findings in <build dir>/<name>_findings/; fails on one.
#
# CORPUS: a directory holds libFuzzer inputs, one per file (bytes as a host
# sends them, lines ending in '\n'), e.g. what <name>_run found or a
# directory of past findings; a file is a recording (`# comment`,
# `SECONDS<TAB>request`, `<SECONDS<TAB>reply`): its request lines become
# seeds of at most 1 KB of whole lines each, read by the replay at run time
# and written by <name>_seeds at build time. Relative paths are from the
# calling CMakeLists.txt. TIMEOUT (default 10) bounds one input, in the
# replay (an alarm) and under libFuzzer (-timeout).
#
# Instrumentation: both programs compile the core's sources themselves (a
# copy of <core target>: its SOURCES, include directories, definitions,
# options and C standard; one copy per core and per program kind, shared by
# every fuzz target of that core, lines and frames), so the adopter's core target stays as they build
# it, while the fuzzed core carries libFuzzer's coverage (-fsanitize=fuzzer-no-link)
# and both carry ASan + UBSan: without that, libFuzzer would see no edge in
# the core and fuzz blind. The harness, the recorder and the adopter's
# SOURCES are compiled with the same flags. ASan + UBSan are used whenever
# the compiler links them (gcc and clang on Linux and macOS); otherwise the
# replay still checks every invariant but memory errors. An IMPORTED core
# (the prebuilt daran_ascii::daran_ascii of an installed package) has no
# sources: for it the default core is compiled from the installed sources;
# a core built with an options header must be given as the target that
# daran_ascii_add_library() made.
#
# daran_ascii_add_can_fuzz_target(<name> ...the same arguments...)
#
# fuzzes the port's CAN glue and HAL with frames (testkit/fuzz/fuzz_can_target.c):
# the test-port file must give can_port, and should give can_deliver. The
# same targets; <name>_replay also takes --seeds, the kit's built-in seeds,
# which the CTest test <name>_replay always runs (with the CORPUS entries:
# folders of inputs, or input files) and <name>_seeds writes for libFuzzer.
include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/DaranAddLibrary.cmake") # the package's helpers

# <copy>: a static library of <core>'s sources compiled with the extra
# options ARGN, with <core>'s usage requirements.
function(_daran_fuzz_core_copy copy core)
  get_target_property(_sources ${core} SOURCES)
  get_target_property(_dir ${core} SOURCE_DIR)
  set(_c_sources "")
  foreach(_source IN LISTS _sources)
    if(_source MATCHES "^\\$<")
      list(APPEND _c_sources "${_source}") # a generator expression: as given
    elseif(_source MATCHES "\\.c$")
      if(NOT IS_ABSOLUTE "${_source}")
        set(_source "${_dir}/${_source}")
      endif()
      list(APPEND _c_sources "${_source}")
    endif()
  endforeach()
  if(NOT _c_sources)
    message(FATAL_ERROR "daran_ascii_add_fuzz_target: the core target ${core} has no C sources")
  endif()
  add_library(${copy} STATIC ${_c_sources})
  # A source another directory generates must exist before the copy compiles.
  add_dependencies(${copy} ${core})
  target_include_directories(${copy}
    PRIVATE $<TARGET_PROPERTY:${core},INCLUDE_DIRECTORIES>
    PUBLIC $<TARGET_PROPERTY:${core},INTERFACE_INCLUDE_DIRECTORIES>)
  target_compile_definitions(${copy}
    PRIVATE $<TARGET_PROPERTY:${core},COMPILE_DEFINITIONS>
    PUBLIC $<TARGET_PROPERTY:${core},INTERFACE_COMPILE_DEFINITIONS>)
  target_compile_options(${copy} PRIVATE $<TARGET_PROPERTY:${core},COMPILE_OPTIONS> ${ARGN})
  foreach(_property IN ITEMS C_STANDARD C_STANDARD_REQUIRED C_EXTENSIONS)
    get_target_property(_value ${core} ${_property})
    if(NOT _value STREQUAL "_value-NOTFOUND")
      set_target_properties(${copy} PROPERTIES ${_property} ${_value})
    endif()
  endforeach()
  get_target_property(_libraries ${core} LINK_LIBRARIES)
  if(_libraries)
    target_link_libraries(${copy} PUBLIC ${_libraries})
  endif()
endfunction()

function(daran_ascii_add_fuzz_target name)
  _daran_add_fuzz_target(daran_ascii_add_fuzz_target LINES ${name} ${ARGN})
endfunction()

function(daran_ascii_add_can_fuzz_target name)
  _daran_add_fuzz_target(daran_ascii_add_can_fuzz_target FRAMES ${name} ${ARGN})
endfunction()

# <function> <LINES or FRAMES> <name> <arguments of the function>
function(_daran_add_fuzz_target function input name)
  set(_caller "${function}(${name})")
  cmake_parse_arguments(PARSE_ARGV 3 arg "" "LIBRARY;SECONDS;TIMEOUT"
                        "SOURCES;INCLUDE_DIRECTORIES;CORPUS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_caller}: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  _daran_check_core("${_caller}" "${arg_LIBRARY}")
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "${_caller}: SOURCES must give the test-port "
                        "file (daran_test_port()) and the HAL's sources")
  endif()
  if(NOT arg_SECONDS)
    set(arg_SECONDS 20)
  endif()
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 10)
  endif()
  _daran_package_dir(_testkit "${_caller}" testkit
                     fuzz/fuzz_port_target.c fuzz/fuzz_can_target.c recorder/recorder.c)
  set(_fuzz "${_testkit}/fuzz")
  set(_recorder "${_testkit}/recorder/recorder.c")

  # The core: an alias is its target; an imported one has no sources.
  set(_core "${arg_LIBRARY}")
  get_target_property(_aliased ${_core} ALIASED_TARGET)
  if(_aliased)
    set(_core "${_aliased}")
  endif()
  get_target_property(_imported ${_core} IMPORTED)
  if(_imported)
    get_target_property(_definitions ${_core} INTERFACE_COMPILE_DEFINITIONS)
    if("${_definitions}" MATCHES "DARAN_CONFIG_HEADER|DARAN_OMIT_LIST_SIGNATURE")
      message(FATAL_ERROR "${_caller}: ${arg_LIBRARY} is prebuilt with "
                          "an options header; give the core that daran_ascii_add_library() makes "
                          "for that header instead")
    endif()
    set(_core daran_fuzz_default_core)
    if(NOT TARGET ${_core})
      daran_ascii_add_library(${_core})
    endif()
  endif()

  _daran_check_flags(DARAN_FUZZ_HAVE_SANITIZERS "int main(void) { return 0; }"
                          -fsanitize=address,undefined)
  set(_sanitize "")
  if(DARAN_FUZZ_HAVE_SANITIZERS)
    set(_sanitize -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  endif()
  # The harness's own code keeps to the library's warnings (not as errors:
  # a newer compiler must not break an adopter's build).
  if(input STREQUAL "FRAMES")
    set(_harness_sources "${_fuzz}/fuzz_can_target.c" "${_fuzz}/fuzz_can_seeds.c")
    set(_replay_definitions DARAN_FUZZ_CAN_TARGET)
  else()
    set(_harness_sources "${_fuzz}/fuzz_port_target.c" "${_fuzz}/fuzz_checks.c")
    set(_replay_definitions "")
  endif()
  list(APPEND _harness_sources "${_fuzz}/fuzz_rows.c" "${_recorder}")
  set(_warnings -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wstrict-prototypes
                -Wmissing-prototypes)
  set(_includes "${_fuzz}" "${_testkit}/include" ${arg_INCLUDE_DIRECTORIES})
  # Room for every call of a line (the recorder's log; the same value in the
  # harness and the recorder, which share the struct).
  set(_definitions DARAN_RECORDER_CALLS_MAX=256)

  # The replay: any compiler.
  # One copy of a core per set of flags, shared by its fuzz targets (lines
  # and frames of one port compile it once).
  string(MAKE_C_IDENTIFIER "${_core}" _core_id)
  set(_replay_core daran_fuzz_${_core_id}_replay_core)
  if(NOT TARGET ${_replay_core})
    _daran_fuzz_core_copy(${_replay_core} ${_core} ${_sanitize})
  endif()
  add_executable(${name}_replay ${_harness_sources} "${_fuzz}/fuzz_recording.c"
                 "${_fuzz}/fuzz_replay_main.c" ${arg_SOURCES})
  target_include_directories(${name}_replay PRIVATE ${_includes})
  target_compile_definitions(${name}_replay PRIVATE ${_definitions} ${_replay_definitions})
  target_compile_options(${name}_replay PRIVATE ${_sanitize})
  target_link_options(${name}_replay PRIVATE ${_sanitize})
  target_link_libraries(${name}_replay PRIVATE ${_replay_core})
  set_target_properties(${name}_replay PROPERTIES C_STANDARD 11)
  set_source_files_properties(${_harness_sources} "${_fuzz}/fuzz_recording.c"
    "${_fuzz}/fuzz_replay_main.c" PROPERTIES COMPILE_OPTIONS "${_warnings}")

  set(_corpus_args "")
  set(_corpus_dirs "")
  set(_recordings "")
  foreach(_entry IN LISTS arg_CORPUS)
    get_filename_component(_entry "${_entry}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    if(IS_DIRECTORY "${_entry}")
      list(APPEND _corpus_args "${_entry}")
      list(APPEND _corpus_dirs "${_entry}")
    elseif(EXISTS "${_entry}" AND input STREQUAL "FRAMES")
      list(APPEND _corpus_args "${_entry}") # one input
    elseif(EXISTS "${_entry}")
      list(APPEND _corpus_args --recording "${_entry}")
      list(APPEND _recordings "${_entry}")
    else()
      message(FATAL_ERROR "${_caller}: CORPUS entry ${_entry} not found")
    endif()
  endforeach()
  if(input STREQUAL "FRAMES")
    list(PREPEND _corpus_args --seeds) # the built-in seeds, always
  endif()
  if(_corpus_args)
    add_test(NAME ${name}_replay
             COMMAND ${name}_replay --timeout ${arg_TIMEOUT} ${_corpus_args})
    set_tests_properties(${name}_replay PROPERTIES LABELS fuzz)
  endif()

  # The libFuzzer harness: clang only.
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
    message(STATUS "${_caller}: ${CMAKE_C_COMPILER_ID} is not clang: "
                   "only ${name}_replay is built (configure a build folder with "
                   "-DCMAKE_C_COMPILER=clang-14 for the libFuzzer harness ${name} and ${name}_run)")
    return()
  endif()
  _daran_check_flags(DARAN_FUZZ_HAVE_LIBFUZZER
    "#include <stddef.h>\n#include <stdint.h>\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; return (int)n * 0; }"
    -fsanitize=fuzzer,address,undefined)
  if(NOT DARAN_FUZZ_HAVE_LIBFUZZER)
    message(STATUS "${_caller}: ${CMAKE_C_COMPILER} does not link "
                   "-fsanitize=fuzzer (libFuzzer); only ${name}_replay is built")
    return()
  endif()
  # -O1: a Debug build's -O0 would fuzz several times slower.
  set(_fuzzer_flags -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                    -fno-omit-frame-pointer -O1)
  set(_fuzzer_core daran_fuzz_${_core_id}_fuzzer_core)
  if(NOT TARGET ${_fuzzer_core})
    _daran_fuzz_core_copy(${_fuzzer_core} ${_core} ${_fuzzer_flags})
  endif()
  add_executable(${name} ${_harness_sources} ${arg_SOURCES})
  target_include_directories(${name} PRIVATE ${_includes})
  target_compile_definitions(${name} PRIVATE ${_definitions})
  target_compile_options(${name} PRIVATE ${_fuzzer_flags})
  target_link_options(${name} PRIVATE -fsanitize=fuzzer,address,undefined)
  target_link_libraries(${name} PRIVATE ${_fuzzer_core})
  set_target_properties(${name} PROPERTIES C_STANDARD 11)

  set(_seeds "${CMAKE_CURRENT_BINARY_DIR}/${name}_seeds")
  set(_stamp "${CMAKE_CURRENT_BINARY_DIR}/${name}_seeds.stamp")
  set(_seed_commands COMMAND ${CMAKE_COMMAND} -E rm -rf "${_seeds}"
                     COMMAND ${CMAKE_COMMAND} -E make_directory "${_seeds}")
  if(input STREQUAL "FRAMES")
    list(APPEND _seed_commands COMMAND ${name}_replay --write-seeds "${_seeds}" --seeds)
  elseif(_recordings)
    set(_recording_args "")
    foreach(_recording IN LISTS _recordings)
      list(APPEND _recording_args --recording "${_recording}")
    endforeach()
    list(APPEND _seed_commands COMMAND ${name}_replay --write-seeds "${_seeds}" ${_recording_args})
  endif()
  add_custom_command(OUTPUT "${_stamp}" ${_seed_commands}
                     COMMAND ${CMAKE_COMMAND} -E touch "${_stamp}"
                     DEPENDS ${_recordings} ${name}_replay
                     COMMENT "Seeds of ${name}"
                     VERBATIM)
  add_custom_target(${name}_seeds ALL DEPENDS "${_stamp}")

  set(_work "${CMAKE_CURRENT_BINARY_DIR}/${name}_corpus")
  set(_findings "${CMAKE_CURRENT_BINARY_DIR}/${name}_findings")
  add_custom_target(${name}_run
    COMMAND ${CMAKE_COMMAND} -E make_directory "${_work}" "${_findings}"
    COMMAND $<TARGET_FILE:${name}> -max_total_time=${arg_SECONDS} -timeout=${arg_TIMEOUT}
            -max_len=4096 -rss_limit_mb=2048 -print_final_stats=1
            -artifact_prefix=${_findings}/ "${_work}" "${_seeds}" ${_corpus_dirs}
    DEPENDS ${name} ${name}_seeds
    COMMENT "Fuzzing ${name} for ${arg_SECONDS} s (findings go to ${_findings}/)"
    USES_TERMINAL
    VERBATIM)
endfunction()

# Installs the harness's sources under <DARAN_INSTALL_DATADIR>/testkit/fuzz
# for daran_ascii_add_fuzz_target() of an installed package (the module
# itself is installed with the package's other modules). Called once by the
# library's own build.
function(daran_ascii_install_fuzz_sources)
  if(NOT DARAN_INSTALL)
    return()
  endif()
  get_property(_root GLOBAL PROPERTY DARAN_ASCII_ROOT)
  file(GLOB _files "${_root}/testkit/fuzz/*.c" "${_root}/testkit/fuzz/*.h"
                   "${_root}/testkit/fuzz/README.md")
  install(FILES ${_files} DESTINATION "${DARAN_INSTALL_DATADIR}/testkit/fuzz")
endfunction()
