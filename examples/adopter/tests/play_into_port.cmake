# Play a recorded session into the X1's port program with daran-replay and
# require a reply to every query and no error reply: the X1 accepts every
# line the vendor's client sends.
#   cmake -DREPLAY=<daran-replay> -DPROGRAM=<acme-port> -DSESSION=<file> -P play_into_port.cmake
execute_process(
  COMMAND ${REPLAY} --target program --program ${PROGRAM} --no-pace ${SESSION}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE replies
  ERROR_VARIABLE diagnostics)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "daran-replay failed (${status}):\n${diagnostics}")
endif()
if(replies MATCHES "error: [a-z ]+")
  message(FATAL_ERROR "the X1 refused a line of the session: ${CMAKE_MATCH_0}\n${replies}")
endif()
string(REGEX MATCHALL "\n" lines "${replies}")
list(LENGTH lines count)
if(count LESS 10)
  message(FATAL_ERROR "only ${count} reply lines from the X1:\n${replies}\n${diagnostics}")
endif()
message(STATUS "${count} reply lines, no error")
