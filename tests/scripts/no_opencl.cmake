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

# In the sanitizer tree (CI's build without OpenCL), the unit tests whose answer depends on the build having no
# OpenCL backend, and the oracles on the worker threads, run under ASan/UBSan from the one test program: the device
# choice and the commands that refuse OpenCL work (fast), and the reference light and root-contact solvers giving
# the same answer on any number of threads (about 50 s there). The whole unit suite under the sanitizers takes 22
# minutes on 2 cores, too long for CI; it runs there with `ctest -L unit` (README). Label "input", the label
# that tree's CI run selects; CI builds heliostand_tests there for them.
if(HELIOSTAND_SANITIZE)
  add_test(NAME unit.no_opencl.device_choice_and_refusals
           COMMAND heliostand_tests "--gtest_filter=ComputeBackend.*:Cli.*:CheckCli.*:GrowCli.UnknownDevice*:BenchLightEvaluationsCli.*:BenchStandCli.BadInput*:BenchLightStandCli.BadScenario*")
  add_test(NAME unit.no_opencl.reference_solvers_on_threads
           COMMAND heliostand_tests "--gtest_filter=*ReferenceLightSolverThreads.*:ReferenceRootFieldThreads.*")
  set_tests_properties(unit.no_opencl.device_choice_and_refusals unit.no_opencl.reference_solvers_on_threads
                       PROPERTIES LABELS input TIMEOUT 600 ENVIRONMENT "${HELIOSTAND_TEST_ENV}"
                                  ENVIRONMENT_MODIFICATION "${HELIOSTAND_LSAN_SUPPRESSIONS}"
                                  FAIL_REGULAR_EXPRESSION "\\[  PASSED  \\] 0 tests")  # a filter that matches nothing
endif()
