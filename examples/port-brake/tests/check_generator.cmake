# Runs tools/gen_property_index.py on an options header, as the library's
# build does, and checks the verdict:
#   cmake -DPYTHON=<python3> -DSOURCE=<daran-ascii tree> -DHEADER=<options.h>
#         -DOUT=<scratch file> [-DEXPECT_ERROR=<text of the message>] -P check_generator.cmake
# Without EXPECT_ERROR the header must be accepted; with it, refused with a
# message that contains EXPECT_ERROR.
get_filename_component(_dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${_dir})
execute_process(
  COMMAND ${PYTHON} ${SOURCE}/tools/gen_property_index.py
          --list ${SOURCE}/include/daran_properties.h --config ${HEADER} --out ${OUT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(DEFINED EXPECT_ERROR)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${HEADER} was accepted; the generator should have refused it")
  endif()
  string(FIND "${err}${out}" "${EXPECT_ERROR}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${HEADER} was refused, but not for \"${EXPECT_ERROR}\":\n${err}${out}")
  endif()
  message(STATUS "refused as it should be: ${err}")
elseif(NOT rc EQUAL 0)
  message(FATAL_ERROR "${HEADER} was refused:\n${err}${out}")
endif()
