// Seed 000's light response at stand scale (issue 4, item 5), on whole plantations grown by the stand manager:
//
//   1. Gap regrowth: the example plantation (stands/sobetsu) grown with its first thinning and, as the control,
//      without it. Every residual tree next to a removed one is measured: how far its living foliage reaches
//      toward the gap (the farthest leaf-ball centre along the horizontal direction to the removed stem), in
//      the thinned run and in the control. Seed 000 Fig. 11: the crown extends further into the gap.
//   2. Self-thinning: a dense unthinned young plantation (generated here: 64 trees at 1.5 m spacing, 4 444
//      stems/ha, heights spread ±30 %) loses its suppressed trees to light, the shorter ones.
//
//   stand_light_validation OUT_DIR [--years N] [--cutoff-m M] [--far-field-cell-m C] [--hand-over-cells H]
//                          [--seed S]
//
// --cutoff-m sets the light's near-field cut-off (LightParameters::cutoff_m; default the model's) in all runs:
// the findings measured at another cut-off (docs/light.md "2 m tried and not kept"); --far-field-cell-m likewise
// the far field's voxel edge (LightParameters::far_field_cell_m; docs/light.md "Coarser far-field cells tried and
// not kept"), and --hand-over-cells where the far field takes over (LightParameters::far_field_hand_over_cells;
// docs/light.md "2.5 m and nearer hand-overs tried and not kept"). The gap is grown with four seeds (the
// example's own and 2, 3, 4) and judged on their mean, since one draw varies as much as the effect; --seed S
// replaces them and the dense plantation's own seed (3) by S alone: one draw of each finding.
//
// Writes every run's full outputs (stand.pvd, tables) under OUT_DIR, and OUT_DIR/stand_light.md with the
// measurements. Exit status 0 when both findings hold, 1 when one does not, 2 on bad usage or a report that cannot
// be written (refused before the runs).
// Cost is kept CI-sized: roots off, a coarse sky (8 x 16 patches), 10 years.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/seed_option.hpp"
#include "io/output_folder.hpp"
#include "rng/random_stream.hpp"
#include "run/simulation.hpp"
#include "scenario/scenario.hpp"
#include "stand/stand.hpp"

namespace fs = std::filesystem;
using namespace heliostand;

namespace {

// What the measurements need of a tree at the end of a run.
struct TreeRecord {
  glm::dvec3 stem{0.0};
  std::vector<glm::dvec3> foliage;  // leaf-ball centres
  TreeStatus status = TreeStatus::alive;
  int status_age = -1;
  double height_m = 0;
};

using StandRecord = std::map<std::string, TreeRecord>;  // by survey label

StandRecord record_of(const Stand& stand) {
  StandRecord record;
  for (const StandTree& tree : stand.trees()) {
    TreeRecord& r = record[tree.label];
    r.stem = tree.conifer.stem_base();
    if (tree.alive())
      for (const LeafBall& ball : tree.conifer.leaf_balls()) r.foliage.push_back(ball.centre);
    r.status = tree.status;
    r.status_age = tree.status_changed_at_age;
    r.height_m = tree.conifer.height_m();
  }
  return record;
}

// Runs the scenario into `folder`; returns the stand at year 0 and at the end.
std::pair<StandRecord, StandRecord> grow(const Scenario& scenario, const fs::path& folder) {
  std::pair<StandRecord, StandRecord> records;
  SimulationOptions options;
  options.output_folder = folder;
  options.force = true;
  options.observe_year = [&](const Stand& stand, int year) {
    if (year == 0) records.first = record_of(stand);
    if (year == scenario.run.years) records.second = record_of(stand);
  };
  run_simulation(scenario, options);
  return records;
}

// What a run of this validation is grown with besides its CI size: years, the light's numerics and the seed.
struct FindingRun {
  int years = 10;
  double cutoff_m = LightParameters{}.cutoff_m;
  double far_field_cell_m = LightParameters{}.far_field_cell_m;
  double hand_over_cells = LightParameters{}.far_field_hand_over_cells;
  std::optional<std::uint64_t> seed;  // unset: each scenario's own
};

void make_ci_sized(Scenario& scenario, FindingRun settings) {
  scenario.roots.enabled = false;
  scenario.light.cutoff_m = settings.cutoff_m;
  scenario.light.far_field_cell_m = settings.far_field_cell_m;
  scenario.light.far_field_hand_over_cells = settings.hand_over_cells;
  scenario.light.sky_bands = 8;
  scenario.light.sky_sectors = 16;
  const int end_age = scenario.stand.age_at_survey_years + settings.years;
  std::erase_if(scenario.thinning, [&](const ThinningEvent& e) { return e.when.stand_age > end_age; });
  scenario.set_years(settings.years);
  if (settings.seed) scenario.set_seed(*settings.seed);
}

// Farthest reach of the foliage from the stem along the horizontal unit vector `toward`.
double reach(const TreeRecord& tree, glm::dvec3 toward) {
  double farthest = 0.0;
  for (const auto& centre : tree.foliage) farthest = std::max(farthest, glm::dot(centre - tree.stem, toward));
  return farthest;
}

struct Finding {
  std::string text;
  bool holds = false;
};

// --- 1. Gap regrowth --------------------------------------------------------------------------------------

constexpr double gap_neighbour_distance_m = 4.0;  // residual trees this close to a removed stem border its gap
// The seeds the gap is grown with when none is given: the example's own (1) and three more. One draw's mean
// difference spreads over +0.08 to +0.19 m between seeds (docs/light.md "Other seeds"), as wide as the effect
// the check asks for, so the check is made on the mean over seeds (each seed a pair of 62-tree runs, ~1 minute).
const std::vector<std::optional<std::uint64_t>> gap_seeds = {std::nullopt, 2, 3, 4};

struct GapDraw {
  std::string seed;
  int neighbours = 0, further = 0;
  double mean_difference_m = 0;
};

// One draw: the example grown with its first thinning and without; the border trees' reach, thinned vs control.
GapDraw gap_draw(const Scenario& example, const fs::path& out, FindingRun settings, std::string& report) {
  Scenario thinned = example;
  make_ci_sized(thinned, settings);
  Scenario control = thinned;
  control.thinning.clear();
  const std::string suffix = settings.seed ? fmt::format("_seed{}", *settings.seed) : "";
  const StandRecord with_gaps = grow(thinned, out / ("gap_thinned" + suffix)).second;
  const StandRecord without = grow(control, out / ("gap_control" + suffix)).second;

  GapDraw draw{std::to_string(thinned.run.seed)};
  report += fmt::format("### Seed {}\n\n", draw.seed);
  report += "| tree | gap tree | distance m | reach thinned | reach control | difference |\n"
            "|---|---|---|---|---|---|\n";
  double sum_difference = 0;
  for (const auto& [label, tree] : with_gaps) {
    if (tree.status != TreeStatus::alive) continue;
    const std::string* gap = nullptr;
    double nearest = gap_neighbour_distance_m;
    for (const auto& [other, removed] : with_gaps) {
      if (removed.status != TreeStatus::removed) continue;
      const double d = std::hypot(removed.stem.x - tree.stem.x, removed.stem.y - tree.stem.y);
      if (d < nearest) nearest = d, gap = &other;
    }
    if (!gap || without.at(label).status != TreeStatus::alive) continue;
    glm::dvec3 toward = with_gaps.at(*gap).stem - tree.stem;
    toward.z = 0;
    toward /= glm::length(toward);
    const double into_gap = reach(tree, toward), beside_neighbour = reach(without.at(label), toward);
    ++draw.neighbours;
    draw.further += into_gap > beside_neighbour;
    sum_difference += into_gap - beside_neighbour;
    report += fmt::format("| {} | {} | {:.2f} | {:.2f} | {:.2f} | {:+.2f} |\n", label, *gap, nearest, into_gap,
                          beside_neighbour, into_gap - beside_neighbour);
  }
  draw.mean_difference_m = draw.neighbours ? sum_difference / draw.neighbours : 0.0;
  report += fmt::format("\nSeed {}: {} of {} further, mean difference {:+.3f} m.\n\n", draw.seed, draw.further,
                        draw.neighbours, draw.mean_difference_m);
  return draw;
}

// Holds when, in every draw, a majority of the border trees reach further toward the gap than in the control, and
// the mean difference over the draws is at least 0.10 m. With --seed, that one draw.
Finding gap_regrowth(const fs::path& source, const fs::path& out, FindingRun settings, std::string& report) {
  const Scenario example = load_scenario(source / "stands" / "sobetsu" / "scenario.toml");
  const int survey_age = example.stand.age_at_survey_years;
  report += fmt::format("## Gap regrowth (example plantation, age {} -> {})\n\n", survey_age,
                        survey_age + settings.years);
  report += "Residual trees within 4 m of a stem removed by the first thinning; reach = farthest living leaf-ball "
            "centre from the stem toward the removed stem (m), thinned run vs the unthinned control, per seed.\n\n";
  const std::vector<std::optional<std::uint64_t>> seeds =
      settings.seed ? std::vector<std::optional<std::uint64_t>>{settings.seed} : gap_seeds;
  std::vector<GapDraw> draws;
  for (const auto& seed : seeds) {
    FindingRun draw_settings = settings;
    draw_settings.seed = seed;
    draws.push_back(gap_draw(example, out, draw_settings, report));
  }
  bool every_draw_a_majority = true;
  double sum_of_means = 0;
  std::string per_seed;
  for (const GapDraw& draw : draws) {
    every_draw_a_majority = every_draw_a_majority && draw.neighbours > 0 && 2 * draw.further > draw.neighbours;
    sum_of_means += draw.mean_difference_m;
    per_seed += fmt::format("{}seed {}: {} of {}, {:+.3f} m", per_seed.empty() ? "" : "; ", draw.seed, draw.further,
                            draw.neighbours, draw.mean_difference_m);
  }
  const double mean = sum_of_means / static_cast<double>(draws.size());
  // 0.1 m in five years: less than one year's elongation of a lit Todomatsu branch (eqs. 7-10), so a crown that
  // answers its light at all gets there; before growth followed light the mean was +0.06 m.
  constexpr double min_mean_m = 0.10;
  Finding finding{fmt::format("gap regrowth: gap neighbours reaching further toward the gap than in the control "
                              "({}); mean difference over {} seed(s) {:+.3f} m (expected: a majority in every "
                              "seed, mean >= {:.2f} m)",
                              per_seed, draws.size(), mean, min_mean_m),
                  every_draw_a_majority && mean >= min_mean_m};
  report += fmt::format("{}\n\n", finding.text);
  return finding;
}

// --- 2. Self-thinning -------------------------------------------------------------------------------------

// A dense young plantation: an 8 x 8 grid at 1.5 m (12 m x 12 m, 4 444 stems/ha), 12 years old, heights drawn
// uniformly in ±30 % of 4.5 m so that some trees are overtopped from the start.
fs::path write_dense_plantation(const fs::path& folder) {
  fs::create_directories(folder);
  std::string survey = "id,x,y,height\n";
  RandomStream random(11, {0x44454E53});  // "DENS"
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      survey += fmt::format("D{:02d},{:.2f},{:.2f},{:.2f}\n", 8 * i + j + 1, 0.75 + 1.5 * i, 0.75 + 1.5 * j,
                            4.5 * random.uniform(0.7, 1.3));
  write_whole_file(folder / "survey.csv", survey, folder / "survey.csv");
  write_whole_file(folder / "scenario.toml",
                   "[stand]\nsurvey = \"survey.csv\"\nage_at_survey = 12\n"
                   "x_min = 0\ny_min = 0\nx_max = 12\ny_max = 12\n"
                   "[run]\nyears = 10\nseed = 3\noutput_interval = 2\n"
                   "[light]\nperiodic = true\n"
                   "[roots]\nenabled = false\n",
                   folder / "scenario.toml");
  return folder / "scenario.toml";
}

Finding self_thinning(const fs::path& out, FindingRun settings, std::string& report) {
  Scenario dense = load_scenario(write_dense_plantation(out / "self_thinning_input"));
  make_ci_sized(dense, settings);
  const auto [start, end] = grow(dense, out / "self_thinning");

  std::map<int, int> deaths_by_age;
  double dead_height = 0, survivor_height = 0;
  int dead = 0, survivors = 0;
  for (const auto& [label, tree] : end) {
    const double surveyed_height = start.at(label).height_m;
    if (tree.status == TreeStatus::dead) {
      ++deaths_by_age[tree.status_age];
      ++dead;
      dead_height += surveyed_height;
    } else {
      ++survivors;
      survivor_height += surveyed_height;
    }
  }
  report += fmt::format("## Self-thinning (dense unthinned plantation, 64 trees at 1.5 m, age {} -> {})\n\n",
                        dense.stand.age_at_survey_years, dense.final_age_years());
  report += "| stand age | trees dead of light |\n|---|---|\n";
  for (const auto& [age, count] : deaths_by_age) report += fmt::format("| {} | {} |\n", age, count);
  const double mean_dead = dead ? dead_height / dead : 0.0, mean_alive = survivors ? survivor_height / survivors : 0.0;
  Finding finding{fmt::format("self-thinning: {} of 64 trees died of light; their mean height at the start {:.2f} m "
                              "vs {:.2f} m for the survivors (expected: deaths, and the dead were the shorter)",
                              dead, mean_dead, mean_alive),
                  dead > 0 && mean_dead < mean_alive};
  report += fmt::format("\n{}\n\n", finding.text);
  return finding;
}

// Throws cannot_write(report, ...) unless `report` can be written: checked before the runs, so that a report the
// program could not write is refused at once, not after minutes of growth. An existing file is opened to append
// (and left as it is); a missing one is tried as its temporary sibling, which is removed, so nothing is left.
void check_report_writable(const fs::path& report) {
  std::error_code ignored;
  if (fs::exists(report, ignored)) {
    errno = 0;
    std::ofstream probe(report, std::ios::binary | std::ios::app);
    if (!probe) throw cannot_write(report, errno);
  } else {
    AtomicFile probe(report);  // never committed: its temporary is deleted when it goes out of scope
    probe.write("");
  }
}

// Both findings, their report written to OUT_DIR/stand_light.md; exit status 1 when one fails.
int run_findings(const fs::path& out, const FindingRun& settings) {
  fs::create_directories(out);
  check_report_writable(out / "stand_light.md");
  std::string report = "# Seed 000 at stand scale\n\nWritten by `stand_light_validation` "
                       "(validation/stand_light). Roots off, sky 8 x 16 patches, near-field cut-off " +
                       fmt::format("{:g} m, far-field cells {:g} m taking over {:g} cell edge(s) beyond it, seed {}.\n\n",
                                   settings.cutoff_m, settings.far_field_cell_m, settings.hand_over_cells,
                                   settings.seed ? std::to_string(*settings.seed)
                                                 : "the gap's own and 2, 3, 4, the dense stand's own");
  std::vector<Finding> findings;
  findings.push_back(gap_regrowth(HELIOSTAND_SOURCE_DIR, out, settings, report));
  findings.push_back(self_thinning(out, settings, report));
  write_whole_file(out / "stand_light.md", report, out / "stand_light.md");
  int failed = 0;
  for (const Finding& f : findings) {
    std::cout << (f.holds ? "holds: " : "FAILS: ") << f.text << "\n";
    failed += !f.holds;
  }
  std::cout << "report: " << (out / "stand_light.md").string() << "\n";
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Seed 000's light response at stand scale: gap regrowth and self-thinning"};
  fs::path out;
  FindingRun settings;
  app.add_option("OUT_DIR", out, "folder for both runs' outputs and stand_light.md")->required();
  app.add_option("--years", settings.years, "years grown in each run")->check(CLI::Range(1, 200));
  app.add_option("--cutoff-m", settings.cutoff_m, "near-field cut-off of the light (m)")
      ->check(CLI::Range(0.5, 50.0));
  app.add_option("--far-field-cell-m", settings.far_field_cell_m, "voxel edge of the light's far field (m)")
      ->check(CLI::Range(0.1, 50.0));
  app.add_option("--hand-over-cells", settings.hand_over_cells,
                 "cell edges beyond the cut-off where the light's far field takes over")
      ->check(CLI::Range(0.0, double(max_far_field_hand_over_cells)));
  app.add_option("--seed", settings.seed,
                 "seed of every run (default: the gap with the example's own seed and 2, 3, 4; the dense stand with "
                 "its own)")
      ->check(seed_check());
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  spdlog::set_level(spdlog::level::warn);
  try {
    return run_findings(out, settings);
  } catch (const std::exception& e) {  // e.g. a run or report that could not be written: never a silent 0
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
