# End-to-end checks of the light commands (need add_devices_command / add_bench_command in src/cli/app.cpp).
add_test(NAME light_cli_devices COMMAND $<TARGET_FILE:heliostand> devices)
set_tests_properties(light_cli_devices PROPERTIES
  ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache"
  PASS_REGULAR_EXPRESSION "reference")
# A tiny benchmark: every row present and the JSON well formed enough to name the culled error. A build
# without OpenCL has the reference rows only.
if(HELIOSTAND_OPENCL)
  add_test(NAME light_cli_bench_small
    COMMAND $<TARGET_FILE:heliostand> bench light --balls 300 --subsample 50)
  set_tests_properties(light_cli_bench_small PROPERTIES
    ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache"
    PASS_REGULAR_EXPRESSION "\"opencl_culled_far_field\": \\{\"seconds\"[^}]*\"error_vs_reference_exact\"")
else()
  add_test(NAME light_cli_bench_small
    COMMAND $<TARGET_FILE:heliostand> bench light --balls 300 --subsample 50 --device none)
  set_tests_properties(light_cli_bench_small PROPERTIES
    PASS_REGULAR_EXPRESSION "\"reference_culled\": \\{\"seconds\"[^}]*\"error_vs_reference_exact\"")
endif()
