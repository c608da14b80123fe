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

# In the sanitizer tree (CI's build without OpenCL), most of the unit suite runs under ASan/UBSan from the one test
# program, in three kinds of entry (label "input", the label that tree's CI run selects; CI builds heliostand_tests
# there for them):
# - the device choice and the commands that refuse OpenCL work (fast);
# - the reference light and root-contact solvers giving the same answer on any number of threads (about 50 s there);
# - every other unit test but those slow under the sanitizers, in two shards of one process each (about 30 s
#   together on 2 cores, ~570 tests). The slow ones (the 208 scenario-limit runs, the hollow-mesh sweeps, the
#   tests that grow stands or time whole commands) take 20 of the whole suite's 22 minutes there, too long for CI;
#   `ctest -L unit` in that tree runs them all (README). A test added later joins the shards unless it matches a
#   pattern below: one that is slow under the sanitizers belongs in HELIOSTAND_SLOW_UNDER_SANITIZERS.
# No test runs in two entries at once (each entry's patterns are left out of the shards), because a test's scratch
# folder carries its name. Each entry fails when its filter matches no test.
if(HELIOSTAND_SANITIZE)
  set(HELIOSTAND_NO_OPENCL_REFUSALS
      "ComputeBackend.*:Cli.*:CheckCli.*:GrowCli.UnknownDevice*:BenchLightEvaluationsCli.*:BenchStandCli.BadInput*:BenchLightStandCli.BadScenario*")
  set(HELIOSTAND_NO_OPENCL_THREADS "*ReferenceLightSolverThreads.*:ReferenceRootFieldThreads.*")
  # Each of these took from a few seconds to minutes a test under ASan/UBSan on 2 cores (docs/performance.md "Most
  # of the unit suite under the sanitizers in CI"): the families whose tests grow a stand or run heliostand, and
  # those that build hollow meshes over many seeds.
  string(JOIN ":" HELIOSTAND_SLOW_UNDER_SANITIZERS
         "ScenarioLimits/KeyAtItsLimit.*" "*HollowSweep.*" "SeedExtremes/*" "StackedHollows.*" "HollowMesh.*"
         "BrokenStem.Roll*" "FigureMeshes.*" "GrowCli.*" "GrowthFromLight.*" "CheckpointCli.*" "CheckpointState.*"
         "BatchResumeCli.*" "ThreadsCli.*" "TriggeredThinning.*" "Calibration.*" "LightCulling.*"
         "LightResponseStand.*" "BenchStandCli.*" "BenchLightStandCli.*" "Backends/LightSolverTest.ShellOfOccluders*")

  function(heliostand_no_opencl_entry name filter)  # ARGN: more environment for the entry
    set(environment ${HELIOSTAND_TEST_ENV} ${ARGN})
    add_test(NAME ${name} COMMAND heliostand_tests "--gtest_filter=${filter}")
    # (The LeakSanitizer suppressions come from tests/CMakeLists.txt, as for every script-registered test.)
    set_tests_properties(${name} PROPERTIES LABELS input TIMEOUT 600 ENVIRONMENT "${environment}"
                                            FAIL_REGULAR_EXPRESSION "\\[  PASSED  \\] 0 tests")  # a filter that matches nothing
  endfunction()
  heliostand_no_opencl_entry(unit.no_opencl.device_choice_and_refusals "${HELIOSTAND_NO_OPENCL_REFUSALS}")
  heliostand_no_opencl_entry(unit.no_opencl.reference_solvers_on_threads "${HELIOSTAND_NO_OPENCL_THREADS}")
  foreach(shard 0 1)
    math(EXPR number "${shard} + 1")
    heliostand_no_opencl_entry(unit.no_opencl.the_rest_${number}_of_2
      "*-${HELIOSTAND_NO_OPENCL_REFUSALS}:${HELIOSTAND_NO_OPENCL_THREADS}:${HELIOSTAND_SLOW_UNDER_SANITIZERS}"
      GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=${shard})
  endforeach()
endif()
