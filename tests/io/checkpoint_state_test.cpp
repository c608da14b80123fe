// The run state of a checkpoint (io/checkpoint_state.hpp) round-trips: a stand grown two years with roots, saved,
// restored into freshly built parts as a resumed run builds them, and saved again gives the same bytes — so every
// field saved is also restored.
#include "io/checkpoint_state.hpp"
#include "io/root_vtk.hpp"

#include <gtest/gtest.h>

#include "compute/compute_backend.hpp"
#include "io/checkpoint_codec.hpp"
#include "io/stand_output.hpp"
#include "io/temp_folder.hpp"
#include "light/make_light_solver.hpp"
#include "scenario/scenario.hpp"
#include "stand/establishment.hpp"
#include "stand/root_zone.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"
#include "tiny_stand_scenario.hpp"

namespace heliostand::checkpoint {
namespace {
namespace fs = std::filesystem;

Scenario tiny_with_roots(const fs::path& folder) {
  return load_scenario(heliostand::testing::write_tiny_stand_scenario(
      folder, "[run]\nyears = 4\nseed = 7\n[light]\nsky_bands = 4\nsky_sectors = 8\n[soil]\nnutrient = 0.5\n"));
}

// The parts of one run over `out`: established and grown `years` years, or (years < 0) empty, for resuming.
struct RunUnderTest {
  RunUnderTest(const Scenario& scenario, const compute::ComputeBackend& backend, const fs::path& out, int years)
      : solver(make_light_solver(backend, light_of(scenario, false))),
        open_solver(make_light_solver(backend, light_of(scenario, true))),
        output({.folder = out,
                .plot_area_m2 = scenario.plot_area_ha() * 1e4,
                .detail = scenario.run.output_detail,
                .compression = scenario.run.vtk_compression,
                .resume = years < 0}),
        stand(scenario.plot_area_ha(), scenario.stand.age_at_survey_years, trees(scenario, years), {}),
        roots(years < 0 ? make_root_zone(scenario, backend) : establish_root_zone(scenario, stand, backend)),
        year(stand, *solver, *open_solver, &*roots, &output, {scenario.run.seed, 1.0, scenario.run.years, 1}, clock) {
    add_root_blocks(*output.vtk(), *roots);
    for (int y = 0; y <= years; ++y) year.run(y);
  }
  static LightParameters light_of(const Scenario& scenario, bool open) {
    LightParameters light = scenario.light;
    light.plot_x_max = scenario.stand.plot.x_max;
    light.plot_y_max = scenario.stand.plot.y_max;
    light.exact = open || light.exact;
    return light;
  }
  static std::vector<StandTree> trees(const Scenario& scenario, int years) {
    EstablishmentReport report;
    return years < 0 ? std::vector<StandTree>{} : establish_stand(scenario, report);
  }
  RunParts parts() { return {stand, &*roots, output, year, clock, progress}; }

  std::unique_ptr<LightSolver> solver, open_solver;
  StandOutput output;
  StageClock clock;
  Stand stand;
  std::optional<RootZone> roots;
  StandYear year;
  RunProgress progress{42, 12.5, "2026-11-23T08:00:00Z", "heliostand grow scenario.toml --out out"};
};

// The state of a run grown `years` years over `out`, saved as a killed run leaves it (the tables' temporaries are
// renamed by the destructor: resuming takes them back).
std::string saved_after(const Scenario& scenario, const compute::ComputeBackend& backend, const fs::path& out,
                        int years) {
  RunUnderTest grown(scenario, backend, out, years);
  return save_run(grown.parts());
}

TEST(CheckpointState, ARestoredRunSavesTheSameBytesItWasRestoredFrom) {
  testing::TempFolder tmp("checkpoint_state");
  const Scenario scenario = tiny_with_roots(tmp.path());
  const auto backend = compute::ComputeBackend::open(compute::DeviceChoice::parse("reference"));
  const std::string saved = saved_after(scenario, backend, tmp.path() / "out", 2);
  ASSERT_GT(saved.size(), 10000u);
  RunUnderTest resumed(scenario, backend, tmp.path() / "out", -1);
  load_run(saved, scenario, resumed.parts());
  EXPECT_EQ(resumed.stand.trees().size(), scenario.survey.trees.size());
  EXPECT_EQ(resumed.stand.stand_age(), scenario.stand.age_at_survey_years + 2);
  const std::string again = save_run(resumed.parts());
  ASSERT_EQ(again.size(), saved.size());
  EXPECT_TRUE(again == saved) << "the restored state saves other bytes";
}

TEST(CheckpointState, ACutOrOutOfStepPayloadIsRefused) {
  testing::TempFolder tmp("checkpoint_state_other");
  const Scenario scenario = tiny_with_roots(tmp.path());
  const auto backend = compute::ComputeBackend::open(compute::DeviceChoice::parse("reference"));
  std::string saved = saved_after(scenario, backend, tmp.path() / "out", 0);
  RunUnderTest resumed(scenario, backend, tmp.path() / "out", -1);
  EXPECT_THROW(load_run(saved.substr(0, saved.size() / 2), scenario, resumed.parts()), CheckpointError);
  saved[0] ^= 0x7f;  // the first section tag
  EXPECT_THROW(load_run(saved, scenario, resumed.parts()), CheckpointError);
}

}  // namespace
}  // namespace heliostand::checkpoint
