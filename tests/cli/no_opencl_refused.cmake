# cmake -P runner of cli.no_opencl.device_opencl_refused (tests/scripts/no_opencl.cmake): checks the exit status
# and the message both, and that no output folder was made.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${HELIOSTAND}" grow "${SCENARIO}" --years 3 --device opencl --out "${OUT}"
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
# 1: a runtime failure (the device is missing from this build), not bad input (2): docs/formats.md, batch summary.
if(NOT status EQUAL 1)
  message(FATAL_ERROR "expected exit status 1, got '${status}':\n${output}")
endif()
if(NOT output MATCHES "device 'opencl'")
  message(FATAL_ERROR "the message does not name the device 'opencl':\n${output}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "${OUT} was created for a device that does not exist")
endif()
