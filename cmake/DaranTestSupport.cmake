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

# The package's root and the test kit's headers, for the functions of this
# module and of DaranConformance.cmake (they run in their callers' scopes).
function(_daran_testkit_dirs caller root_out include_out)
  get_property(_root GLOBAL PROPERTY DARAN_ASCII_ROOT)
  if(NOT _root AND EXISTS "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../testkit/recorder/recorder.c")
    # this module in the source tree, before the package has named its root
    get_filename_component(_root "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  endif()
  if(NOT _root OR NOT EXISTS "${_root}/testkit/recorder/recorder.c"
     OR NOT EXISTS "${_root}/testkit/include/daran_recorder.h")
    message(FATAL_ERROR "${caller}: the test kit's sources are not under '${_root}/testkit' "
                        "(DARAN_ASCII_ROOT); install daran-ascii with them (its default) or use "
                        "it through add_subdirectory")
  endif()
  set(${root_out} "${_root}" PARENT_SCOPE)
  set(${include_out} "${_root}/testkit/include" PARENT_SCOPE)
endfunction()

function(_daran_testkit_check_library caller library)
  if(NOT library)
    message(FATAL_ERROR "${caller}: LIBRARY <core target> is required (a target of "
                        "daran_ascii_add_library(), or daran_ascii::daran_ascii)")
  endif()
  if(NOT TARGET ${library})
    message(FATAL_ERROR "${caller}: LIBRARY ${library} is not a target")
  endif()
endfunction()

function(daran_ascii_add_test_support target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "LIBRARY" "")
  set(_caller "daran_ascii_add_test_support(${target})")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_caller}: unexpected arguments '${arg_UNPARSED_ARGUMENTS}' (usage: "
                        "daran_ascii_add_test_support(<target> LIBRARY <core target>))")
  endif()
  _daran_testkit_check_library("${_caller}" "${arg_LIBRARY}")
  _daran_testkit_dirs("${_caller}" _root _include)

  add_library(${target} STATIC "${_root}/testkit/recorder/recorder.c")
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${_include}>")
  target_link_libraries(${target} PUBLIC ${arg_LIBRARY})
  target_compile_features(${target} PUBLIC c_std_99)
  set_target_properties(${target} PROPERTIES C_EXTENSIONS OFF)
endfunction()
