# Runs one transcript through daran-sim and compares stdout with the
# .expected file byte for byte.
#   cmake -DSIM=<daran-sim> -DNAME=<transcript dir>/<name> -DWORK=<dir>
#         [-DUPDATE=1] -P run_transcript.cmake
# <name>.txt is stdin, <name>.expected the exact stdout; <name>.args, if
# present, holds extra command-line options on its first line, where @NVM@
# stands for an empty scratch directory.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/nvm)
set(args "")
if(EXISTS ${NAME}.args)
  file(STRINGS ${NAME}.args line LIMIT_COUNT 1)
  string(REPLACE "@NVM@" "${WORK}/nvm" line "${line}")
  separate_arguments(args UNIX_COMMAND "${line}")
endif()
execute_process(COMMAND ${SIM} ${args}
  INPUT_FILE ${NAME}.txt
  OUTPUT_FILE ${WORK}/stdout
  ERROR_FILE ${WORK}/stderr
  RESULT_VARIABLE rc
  TIMEOUT 60)
if(NOT rc EQUAL 0)
  file(READ ${WORK}/stderr err)
  message(FATAL_ERROR "daran-sim exited with ${rc}:\n${err}")
endif()
if(UPDATE)
  configure_file(${WORK}/stdout ${NAME}.expected COPYONLY)
  return()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/stdout ${NAME}.expected
  RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  execute_process(COMMAND diff -u ${NAME}.expected ${WORK}/stdout)
  message(FATAL_ERROR "stdout differs from ${NAME}.expected (actual output: ${WORK}/stdout)")
endif()
