# A build without its OpenCL backend (HELIOSTAND_OPENCL=OFF, CI's sanitizer tree build-san) must refuse
# `--device opencl` before it writes anything, with exit status 1 (a runtime failure) and a message naming the device, and grow the
# tiny stand on the reference solvers with `--device auto`. Label "input", so the sanitizer tree runs them.
if(HELIOSTAND_OPENCL)
  return()
endif()
set(NO_OPENCL_OUT ${PROJECT_BINARY_DIR}/tests/no_opencl)
add_test(NAME cli.no_opencl.device_opencl_refused
         COMMAND ${CMAKE_COMMAND} -DHELIOSTAND=$<TARGET_FILE:heliostand>
                 -DSCENARIO=${PROJECT_SOURCE_DIR}/stands/tiny/scenario.toml -DOUT=${NO_OPENCL_OUT}/refused
                 -P ${PROJECT_SOURCE_DIR}/tests/cli/no_opencl_refused.cmake)
add_test(NAME cli.no_opencl.auto_grows_on_reference
         COMMAND $<TARGET_FILE:heliostand> -q grow ${PROJECT_SOURCE_DIR}/stands/tiny/scenario.toml --years 3 --no-vtk
                 --device auto --force --out ${NO_OPENCL_OUT}/auto)
set_tests_properties(cli.no_opencl.device_opencl_refused cli.no_opencl.auto_grows_on_reference
                     PROPERTIES LABELS input TIMEOUT 300)
