# Unity test programs: finds Unity (cmake/FindUnity.cmake; a missing Unity
# stops the configuration and names `tools/install-deps test`) and defines
#
#   daran_add_unity_test(<name> <source>...)
#
# One host test program per call: an executable <name> built from the
# sources, linked to unity::unity and daran_ascii (the core's internal headers
# in src/ are visible), registered with CTest as <name>. The program's main()
# ends with `return UNITY_END();`: the exit status is the number of failed
# cases, and CTest also fails the test whenever Unity's summary line counts a
# failure (an exit status of 256 failures would otherwise read as 0).
# Host only: a target test image also needs a startup, a linker script and
# daran_test_putchar() (see tests/support/unity_config.h); the cortex-m4 build
# makes its images with daran_target_unity_image() in tests/target/CMakeLists.txt.
include_guard(GLOBAL)

if(NOT "${CMAKE_CURRENT_LIST_DIR}" IN_LIST CMAKE_MODULE_PATH)
  list(APPEND CMAKE_MODULE_PATH "${CMAKE_CURRENT_LIST_DIR}")
endif()
find_package(Unity REQUIRED)

# tests/support: the stub HAL (stub_hal.h) and float_bits.h every test program may use.
if(NOT TARGET daran_stub_hal AND NOT CMAKE_CROSSCOMPILING)
  add_library(daran_stub_hal STATIC ${PROJECT_SOURCE_DIR}/tests/support/stub_hal.c)
  target_include_directories(daran_stub_hal PUBLIC ${PROJECT_SOURCE_DIR}/tests/support)
  target_link_libraries(daran_stub_hal PUBLIC daran_ascii)
endif()

function(daran_add_unity_test name)
  if(CMAKE_CROSSCOMPILING)
    message(FATAL_ERROR "daran_add_unity_test(${name}): host programs only; "
                        "a target test image links unity::unity itself")
  endif()
  if(NOT ARGN)
    message(FATAL_ERROR "daran_add_unity_test(${name}): no source file given")
  endif()
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE daran_ascii unity::unity daran_stub_hal)
  target_include_directories(${name} PRIVATE ${DARAN_CORE_INTERNAL_INCLUDES})
  add_test(NAME ${name} COMMAND ${name})
  set_tests_properties(${name} PROPERTIES FAIL_REGULAR_EXPRESSION "[1-9][0-9]* Failures")
endfunction()
