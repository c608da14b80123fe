# Runs a command and checks both its exit status and its output, for CTest checks of a program's messages.
# CTest's PASS_REGULAR_EXPRESSION alone ignores the exit status (a crash after the right line would pass), so the
# script-registered tests run through this instead:
#   cmake -DEXPECT_EXIT=N -DEXPECT_OUTPUT=REGEX -P expect_exit_and_output.cmake COMMAND [ARG...]
# REGEX (CMake regular expression) must match stdout and stderr together. Fails with a message saying which check
# failed and what the command printed.
if(NOT DEFINED EXPECT_EXIT OR NOT DEFINED EXPECT_OUTPUT)
  message(FATAL_ERROR "usage: cmake -DEXPECT_EXIT=N -DEXPECT_OUTPUT=REGEX -P expect_exit_and_output.cmake COMMAND [ARG...]")
endif()

# The command is everything after this script's path on the cmake command line.
set(command)
set(after_script FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE 1 ${last})
  if(after_script)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif(CMAKE_ARGV${i} STREQUAL CMAKE_CURRENT_LIST_FILE OR CMAKE_ARGV${i} MATCHES "expect_exit_and_output\\.cmake$")
    set(after_script TRUE)
  endif()
endforeach()
if(NOT command)
  message(FATAL_ERROR "expect_exit_and_output.cmake: no command given after the script")
endif()

execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
set(problems)
if(NOT status STREQUAL "${EXPECT_EXIT}")
  list(APPEND problems "exit status ${status}, expected ${EXPECT_EXIT}")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  list(APPEND problems "output does not match: ${EXPECT_OUTPUT}")
endif()
if(problems)
  string(REPLACE ";" "; " problems "${problems}")
  message(FATAL_ERROR "FAILED (${problems}): ${command}")
endif()
message("PASSED: exit status ${status} and output as expected")
