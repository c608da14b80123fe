# End-to-end checks of the light commands (need add_devices_command / add_bench_command in src/cli/app.cpp), exit
# status 0 and the expected output both (tests/expect_exit_and_output.cmake).
set(LIGHT_EXPECT ${CMAKE_COMMAND} -DEXPECT_EXIT=0)
set(LIGHT_EXPECT_SCRIPT -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake)
add_test(NAME light_cli_devices
  COMMAND ${LIGHT_EXPECT} "-DEXPECT_OUTPUT=reference" ${LIGHT_EXPECT_SCRIPT} $<TARGET_FILE:heliostand> devices)
set_tests_properties(light_cli_devices PROPERTIES
  ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
# A tiny benchmark: every row present and the JSON well formed enough to name the culled error (the row's fields
# start on lines of their own: [^"]* takes the line break and the indent). A build without OpenCL has the reference
# rows only.
if(HELIOSTAND_OPENCL)
  add_test(NAME light_cli_bench_small
    COMMAND ${LIGHT_EXPECT}
            "-DEXPECT_OUTPUT=\"opencl_culled_far_field\": \\{[^\"]*\"seconds\"[^}]*\"error_vs_reference_exact\""
            ${LIGHT_EXPECT_SCRIPT} $<TARGET_FILE:heliostand> bench light --balls 300 --subsample 50)
  set_tests_properties(light_cli_bench_small PROPERTIES
    ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
else()
  add_test(NAME light_cli_bench_small
    COMMAND ${LIGHT_EXPECT}
            "-DEXPECT_OUTPUT=\"reference_culled\": \\{[^\"]*\"seconds\"[^}]*\"error_vs_reference_exact\""
            ${LIGHT_EXPECT_SCRIPT} $<TARGET_FILE:heliostand> bench light --balls 300 --subsample 50 --device none)
endif()
