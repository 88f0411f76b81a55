# The recording HAL (testkit/include/daran_recorder.h) for a core of the
# adopter's options:
#
#   daran_ascii_add_test_support(<target> LIBRARY <core target>)
#
# makes the static library <target> from the recorder's source
# (<root>/testkit/recorder/recorder.c), compiled against <core target> (a
# library of daran_ascii_add_library(), or daran_ascii::daran_ascii): the
# recorder's store and names follow that core's options header and property
# list, so it must be built per core. Linking <target> gives daran_recorder.h,
# daran_recorder_unity.h, daran_test_port.h and the core. The Unity
# assertions (daran_recorder_unity.h) are a header only: a test that includes
# it links Unity itself. <root> is the source tree, or
# <prefix>/share/daran_ascii in the installed package (global property
# DARAN_ASCII_ROOT). The prebuilt daran_ascii::test_support is the same for
# the default core.
include_guard(GLOBAL)

include("${CMAKE_CURRENT_LIST_DIR}/DaranAddLibrary.cmake") # the package's helpers

function(daran_ascii_add_test_support target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "LIBRARY" "")
  set(_caller "daran_ascii_add_test_support(${target})")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_caller}: unexpected arguments '${arg_UNPARSED_ARGUMENTS}' (usage: "
                        "daran_ascii_add_test_support(<target> LIBRARY <core target>))")
  endif()
  _daran_check_core("${_caller}" "${arg_LIBRARY}")
  _daran_package_dir(_testkit "${_caller}" testkit recorder/recorder.c include/daran_recorder.h)
  set(_include "${_testkit}/include")

  add_library(${target} STATIC "${_testkit}/recorder/recorder.c")
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${_include}>")
  target_link_libraries(${target} PUBLIC ${arg_LIBRARY})
  target_compile_features(${target} PUBLIC c_std_99)
  set_target_properties(${target} PROPERTIES C_EXTENSIONS OFF)
endfunction()
