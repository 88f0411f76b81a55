# Configure tests/porting/refused with OPTIONS_HEADER and require the
# configure to fail with a message that names the header and contains EXPECT.
#   cmake -DSOURCE=<repo> -DOPTIONS_HEADER=<file> -DEXPECT=<text> -DWORK=<dir> -P check_refused_header.cmake
file(REMOVE_RECURSE "${WORK}")
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/tests/porting/refused -B ${WORK} -G Ninja
          -DDARAN_SOURCE_DIR=${SOURCE} -DOPTIONS_HEADER=${OPTIONS_HEADER}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "the configure with ${OPTIONS_HEADER} succeeded; it must be refused")
endif()
string(REGEX REPLACE "[ \n]+" " " text "${out} ${err}")
get_filename_component(name "${OPTIONS_HEADER}" NAME)
if(NOT text MATCHES "${name}")
  message(FATAL_ERROR "the refusal does not name the header ${name}:\n${err}")
endif()
string(FIND "${text}" "${EXPECT}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the refusal does not say '${EXPECT}':\n${err}")
endif()
message(STATUS "refused as expected: ${EXPECT}")
