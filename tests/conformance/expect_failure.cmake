# Runs a conformance program over a deliberately broken HAL and passes only
# when the suite caught it: exit status 1, the summary line with failures,
# and a failure report matching EXPECT (the requirement and its subject).
#   cmake -DPROGRAM=<program> -DEXPECT=<regex> -P expect_failure.cmake
execute_process(COMMAND "${PROGRAM}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "the conformance suite passed a broken HAL:\n${out}${err}")
endif()
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, not 1 (requirements failed):\n${out}${err}")
endif()
if(NOT out MATCHES "\n[0-9]+ passed, [1-9][0-9]* failed\n$")
  message(FATAL_ERROR "no summary line 'N passed, N failed' at the end:\n${out}")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "no failure matching '${EXPECT}':\n${out}")
endif()
string(REGEX MATCH "${EXPECT}" caught "${out}")
string(REGEX MATCH "[0-9]+ passed, [0-9]+ failed" summary "${out}")
message(STATUS "caught (${summary}): ${caught}")
