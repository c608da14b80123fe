// `heliostand bench light --device`: what is not an OpenCL device or none is a usage error (exit 2), and a device that
// does not exist fails (exit 1, as `grow` fails on one) before any canopy is lit, not after the reference solvers'
// minutes on a large one. The progress lines (no -q) show whether a canopy was lit.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_runner.hpp"
#include "compute/device_choice.hpp"

namespace heliostand::testing {
namespace {

const std::string reference_rows =
    "bench light --balls 300 --subsample 5 --reference-exact-max 1 --reference-culled-max 0";
const std::string canopy_lit = "bench light: 300 balls";

TEST(BenchLightDeviceCli, AWordThatIsNoDeviceIsAUsageError) {
  const CliResult refused = run_cli(reference_rows + " --device bogus");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("--device: device 'bogus': expected opencl, opencl:N (N >= 0), auto or none"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(refused.output.find(canopy_lit), std::string::npos) << "no canopy lit: " << refused.output;
}

// The OpenCL rows on the reference backend would time the reference solvers twice, the second time under OpenCL's
// names: refused, with the flag that runs the reference solvers alone.
TEST(BenchLightDeviceCli, TheReferenceIsRefusedForTheOpenCLRows) {
  const CliResult refused = run_cli(reference_rows + " --device reference");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("the OpenCL rows need an OpenCL device"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("none runs the reference solvers alone"), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find(canopy_lit), std::string::npos) << "no canopy lit: " << refused.output;
}

TEST(BenchLightDeviceCli, AMissingDeviceFailsBeforeAnyCanopyIsLit) {
  const CliResult failed = run_cli(reference_rows + " --device opencl:99");
  EXPECT_EQ(failed.status, 1) << failed.output;
  const std::string why = compute::opencl_backend_built ? "OpenCL device 99 does not exist"
                                                        : "device 'opencl:99': this build of heliostand has no OpenCL "
                                                          "backend; --device none runs the reference solvers alone";
  EXPECT_NE(failed.output.find(why), std::string::npos) << failed.output;
  EXPECT_EQ(failed.output.find(canopy_lit), std::string::npos) << "no canopy lit: " << failed.output;
  EXPECT_EQ(failed.output.find("\"benchmark\""), std::string::npos) << "no JSON: " << failed.output;
}

// The input first: with both a scenario that does not exist and a device that does not, the scenario is the error
// named (as it is in the build without OpenCL, where the default device is the missing one).
TEST(BenchLightDeviceCli, ABadScenarioIsNamedBeforeAMissingDevice) {
  const std::string missing = (scratch_folder("bench-light-device-order") / "no_such_scenario.toml").string();
  const CliResult refused = run_cli("bench light --stand " + missing + " --device opencl:99");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find(missing), std::string::npos) << refused.output;
}

TEST(BenchLightDeviceCli, NoneRunsTheReferenceSolversAlone) {
  const CliResult run = run_cli(reference_rows + " --device none");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("\"opencl_device\": \"none\""), std::string::npos) << run.output;
}

}  // namespace
}  // namespace heliostand::testing
