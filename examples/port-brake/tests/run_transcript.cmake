# Runs daran-port-brake --echo on NAME.txt and compares its stdout with
# NAME.expected byte for byte:
#   cmake -DPROGRAM=<daran-port-brake> -DNAME=<dir>/transcript -DWORK=<dir>
#         [-DUPDATE=1] -P run_transcript.cmake
# UPDATE=1 writes NAME.expected instead (then read it against the protocol
# before committing it).
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${PROGRAM} --echo
  INPUT_FILE ${NAME}.txt
  OUTPUT_FILE ${WORK}/stdout
  ERROR_FILE ${WORK}/stderr
  RESULT_VARIABLE rc
  TIMEOUT 60)
if(NOT rc EQUAL 0)
  file(READ ${WORK}/stderr err)
  message(FATAL_ERROR "${PROGRAM} exited with ${rc}:\n${err}")
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
