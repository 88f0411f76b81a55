# cmake -DPREFIX=<install prefix> -P version_check.cmake: the installed
# version file must accept a request for 0.1 and refuse one for 1.0
# (SameMajorVersion), the way find_package() asks it.
cmake_minimum_required(VERSION 3.20)
file(GLOB _version_file "${PREFIX}/lib*/cmake/daran_ascii/daran_asciiConfigVersion.cmake")
if(NOT _version_file)
  message(FATAL_ERROR "no daran_asciiConfigVersion.cmake under ${PREFIX}")
endif()
foreach(_request IN ITEMS 0.1 1.0)
  string(REPLACE "." ";" _parts "${_request}")
  list(GET _parts 0 PACKAGE_FIND_VERSION_MAJOR)
  list(GET _parts 1 PACKAGE_FIND_VERSION_MINOR)
  set(PACKAGE_FIND_VERSION "${_request}")
  unset(PACKAGE_VERSION_COMPATIBLE)
  include("${_version_file}")
  set(_compatible_${PACKAGE_FIND_VERSION_MAJOR} "${PACKAGE_VERSION_COMPATIBLE}")
endforeach()
if(NOT _compatible_0 OR _compatible_1)
  message(FATAL_ERROR "version ${PACKAGE_VERSION}: 0.1 compatible=${_compatible_0}, "
                      "1.0 compatible=${_compatible_1}; want TRUE and FALSE")
endif()
message(STATUS "daran_ascii ${PACKAGE_VERSION}: a request for 0.1 is accepted, 1.0 refused")
