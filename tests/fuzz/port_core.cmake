# daran_port_core(<target> [<compile option>...]): the core compiled with the
# example port's options header (examples/port-brake/brake_options.h), for
# the fuzz_port harness: its own property index generated from the vendor
# list plus the port's rows, less its omissions, as the example's own build
# makes it. The sources are those of daran_ascii. Included by
# tests/fuzz/CMakeLists.txt (libFuzzer, the options: -fsanitize=fuzzer-no-link)
# and tests/fuzz/replay.cmake (the standalone replay).

set(DARAN_PORT_EXAMPLE_DIR ${PROJECT_SOURCE_DIR}/examples/port-brake)
set(DARAN_PORT_EXAMPLE_OPTIONS ${DARAN_PORT_EXAMPLE_DIR}/brake_options.h)

function(daran_port_core target)
  find_package(Python3 COMPONENTS Interpreter REQUIRED)
  get_target_property(_sources daran_ascii SOURCES)
  get_target_property(_dir daran_ascii SOURCE_DIR)
  set(_gen ${CMAKE_CURRENT_BINARY_DIR}/${target}_generated)
  set(_index ${_gen}/property_index.h)
  add_custom_command(
    OUTPUT ${_index}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${_gen}
    COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/gen_property_index.py
            --list ${PROJECT_SOURCE_DIR}/include/daran_properties.h
            --config ${DARAN_PORT_EXAMPLE_OPTIONS} --out ${_index}
    DEPENDS ${PROJECT_SOURCE_DIR}/tools/gen_property_index.py
            ${PROJECT_SOURCE_DIR}/include/daran_properties.h ${DARAN_PORT_EXAMPLE_OPTIONS}
    COMMENT "Generating the property index of the example port"
    VERBATIM)
  set(_src ${_index})
  foreach(_source IN LISTS _sources)
    if(_source MATCHES "\\.c$")
      if(NOT IS_ABSOLUTE "${_source}")
        set(_source "${_dir}/${_source}")
      endif()
      list(APPEND _src "${_source}")
    endif()
  endforeach()
  add_library(${target} STATIC ${_src})
  # the port's index first: src/table/property_table.c includes "property_index.h"
  target_include_directories(${target} BEFORE PRIVATE ${_gen})
  target_include_directories(${target} PRIVATE ${DARAN_CORE_INTERNAL_INCLUDES})
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_compile_definitions(${target} PUBLIC DARAN_CONFIG_HEADER=${DARAN_PORT_EXAMPLE_OPTIONS})
  target_compile_options(${target} PRIVATE -fno-math-errno ${ARGN})
  set_target_properties(${target} PROPERTIES C_STANDARD 11 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  target_link_libraries(${target} PUBLIC m)
endfunction()
