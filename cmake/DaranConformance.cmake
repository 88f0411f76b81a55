# The conformance suite for an adopter's port (docs/conformance.md):
#
#   daran_ascii_add_conformance_test(<name> LIBRARY <core target>
#                                    SOURCES <test-port file> <HAL sources>...)
#
# builds the program <name> from the suite's sources
# (<root>/testkit/conformance), the recording HAL (<root>/testkit/recorder)
# and SOURCES: the adopter's test-port file, which defines daran_test_port()
# (testkit/include/daran_test_port.h), and the HAL's sources. All of it is
# compiled against <core target> (a library of daran_ascii_add_library(), or
# daran_ascii::daran_ascii), so the suite checks the properties of that
# build: its own rows in, its omitted rows out. CTest runs it as the test
# <name>; it exits non-zero when a requirement fails and prints each failure
# with the lines sent, the replies and the HAL calls expected and seen.
# Headers of the HAL: target_include_directories(<name> PRIVATE ...). The
# program (the suite and the HAL sources) is built with ASan + UBSan where the
# compiler links them; NO_SANITIZERS after the name leaves them out.
#
#   daran_ascii_add_conformance_program(<name> LIBRARY <core target> SOURCES ...)
#
# builds the same program without registering a test (to run it with other
# arguments, e.g. --verbose, or under a wrapper of one's own).
include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/DaranAddLibrary.cmake") # the package's helpers

function(daran_ascii_add_conformance_program name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "NO_SANITIZERS" "LIBRARY" "SOURCES")
  set(_caller "daran_ascii_add_conformance_test(${name})")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_caller}: unexpected arguments '${arg_UNPARSED_ARGUMENTS}' (usage: "
                        "daran_ascii_add_conformance_test(<name> LIBRARY <core target> "
                        "SOURCES <test-port file> <HAL sources>...))")
  endif()
  _daran_check_core("${_caller}" "${arg_LIBRARY}")
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "${_caller}: SOURCES must give the test-port file (it defines "
                        "daran_test_port()) and the HAL's sources")
  endif()
  _daran_package_dir(_testkit "${_caller}" testkit recorder/recorder.c
                     conformance/conformance_sources.cmake)
  set(_include "${_testkit}/include")
  set(_dir "${_testkit}/conformance")
  include("${_dir}/conformance_sources.cmake")
  list(TRANSFORM DARAN_CONFORMANCE_SOURCES PREPEND "${_dir}/")

  add_executable(${name} ${DARAN_CONFORMANCE_SOURCES} "${_testkit}/recorder/recorder.c"
                 ${arg_SOURCES})
  target_include_directories(${name} PRIVATE "${_include}" "${_dir}")
  target_link_libraries(${name} PRIVATE ${arg_LIBRARY})
  if(NOT CMAKE_CROSSCOMPILING)
    target_link_libraries(${name} PRIVATE m)
  endif()
  target_compile_features(${name} PRIVATE c_std_99)
  # The HAL under test runs under ASan + UBSan where the compiler links them,
  # so a HAL that writes out of bounds or overflows fails here too
  # (NO_SANITIZERS: leave the program's flags as the project has them).
  if(NOT arg_NO_SANITIZERS AND NOT CMAKE_CROSSCOMPILING)
    _daran_check_flags(DARAN_FUZZ_HAVE_SANITIZERS "int main(void) { return 0; }"
                            -fsanitize=address,undefined)
    if(DARAN_FUZZ_HAVE_SANITIZERS)
      set(_sanitize -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
      target_compile_options(${name} PRIVATE ${_sanitize})
      target_link_options(${name} PRIVATE ${_sanitize})
    endif()
  endif()
endfunction()

function(daran_ascii_add_conformance_test name)
  daran_ascii_add_conformance_program(${name} ${ARGN})
  add_test(NAME ${name} COMMAND ${name})
endfunction()
