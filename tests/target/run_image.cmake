# Runs one Unity test image under QEMU for CTest and reports QEMU's exit
# status, so that CTest judges a run by both Unity's summary line and the
# status (a test with PASS_REGULAR_EXPRESSION ignores the exit code; the line
# printed here is what FAIL_REGULAR_EXPRESSION catches instead).
#
#   cmake -DQEMU=<command line, space separated> -DELF=<image> -P run_image.cmake
#
# The image's UART0 output (Unity's report) goes straight to standard output.
# QEMU's standard input is /dev/null: the images read nothing.
if(NOT QEMU OR NOT ELF)
  message(FATAL_ERROR "usage: cmake -DQEMU=<qemu command> -DELF=<image.elf> -P run_image.cmake")
endif()
separate_arguments(_qemu UNIX_COMMAND "${QEMU}")
execute_process(COMMAND ${_qemu} -kernel ${ELF}
                INPUT_FILE /dev/null
                RESULT_VARIABLE _status)
message("QEMU exit status ${_status}")
if(NOT _status STREQUAL "0")
  message(FATAL_ERROR "the image failed (exit status ${_status}): after Unity's summary "
                      "line it is the failure count (at most 255); without one, the run "
                      "stopped early (3: a fault, the default exception handler)")
endif()
