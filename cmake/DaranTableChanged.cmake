# daran_property_table_changed(<out>): does this build's options header
# (DARAN_CONFIG_HEADER) or DARAN_PROPERTY_OMIT change the vendor's property
# table? The suites that assume the vendor's 165 rows are left out then
# (tests/CMakeLists.txt, tests/target/CMakeLists.txt).
include_guard(GLOBAL)

function(daran_property_table_changed out)
  set(_changed OFF)
  if(DARAN_PROPERTY_OMIT)
    set(_changed ON)
  endif()
  if(DARAN_CONFIG_HEADER)
    file(READ "${DARAN_CONFIG_HEADER}" _text) # absolute: cmake/DaranOptions.cmake
    if(_text MATCHES "#[ \t]*define[ \t]+DARAN_(PORT_PROPERTY_LIST|OMIT_PROPERTIES|PORT_RANGE_LIST)")
      set(_changed ON)
    endif()
  endif()
  set(${out} ${_changed} PARENT_SCOPE)
endfunction()
