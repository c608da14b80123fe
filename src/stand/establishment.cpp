#include "stand/establishment.hpp"

#include <cmath>
#include <optional>

#include <spdlog/spdlog.h>

#include "rng/random_stream.hpp"
#include "architecture/stem_taper.hpp"
#include "stand/calibration.hpp"
#include "core/parallel_for.hpp"

namespace heliostand {
namespace {

SurveyTarget target_of(const SurveyRecord& record) {
  SurveyTarget target;
  target.age_years = static_cast<int>(std::lround(record.age_years));
  target.height_m = record.height_m;
  // Every tree starts as surveyed, or as imputed where the survey has no value (the imputation is logged once per
  // column by the survey reader): the run starts from the numbers the user sees in `heliostand check`.
  target.crown_radius_m = record.crown_radius_m;
  target.crown_base_m = std::min(record.crown_base_m, record.height_m);
  if (record.height_m > breast_height_m && record.dbh_cm > 0.0) target.dbh_cm = record.dbh_cm;
  return target;
}

// The record's hollows with their random streams fixed: a hollow without its own seed draws from one derived
// from the run seed, the tree and the hollow's place on the tree, so it looks the same in every output year.
std::vector<hollow::HollowSpec> hollows_of(const SurveyRecord& record, std::uint64_t run_seed, int tree_id) {
  constexpr std::uint64_t hollow_tag = 0x484F4C4C;  // "HOLL"
  std::vector<hollow::HollowSpec> hollows;
  for (std::size_t k = 0; k < record.hollows.size(); ++k) {
    hollow::HollowSpec spec = record.hollows[k].spec;
    if (!record.hollows[k].seed_given)
      spec.seed = RandomStream(run_seed, {hollow_tag, static_cast<std::uint64_t>(tree_id), k}).next_u64();
    hollows.push_back(spec);
  }
  return hollows;
}

}  // namespace

std::vector<StandTree> establish_stand(const Scenario& scenario, EstablishmentReport& report) {
  const auto& records = scenario.survey.trees;
  std::vector<std::optional<StandTree>> grown(records.size());
  std::vector<CalibrationResult> fits(records.size());

  parallel_for(records.size(), [&](std::size_t i) {
    const SurveyRecord& record = records[i];
    const SpeciesParameters& species = scenario.species_of(record);
    const int id = static_cast<int>(i);
    const SurveyTarget target = target_of(record);
    fits[i] = calibrate_tree(species, target, scenario.run.seed, id);
    ConiferTree tree = grow_calibrated_tree(species, fits[i].calibration, target.age_years,
                                            {record.x_m, record.y_m, 0.0}, scenario.run.seed, id,
                                            {target.dbh_cm, target.crown_base_m});
    tree.set_light_driven_crown(true);
    grown[i].emplace(StandTree{.id = id,
                               .label = record.id,
                               .species = record.species,
                               .conifer = std::move(tree),
                               .hollows = hollows_of(record, scenario.run.seed, id)});
  });

  report = {};
  std::vector<StandTree> trees;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& fit = fits[i];
    if (fit.status == CalibrationStatus::fitted) {
      ++report.fitted;
    } else if (fit.usable()) {
      ++report.crown_base_off;
      spdlog::debug("tree '{}' ({}:{}): {}", records[i].id, scenario.survey.file.string(), records[i].line,
                    fit.message);
    } else {
      ++report.unusable;
      spdlog::warn("tree '{}' ({}:{}): {}", records[i].id, scenario.survey.file.string(), records[i].line,
                   fit.message);
    }
    trees.push_back(std::move(*grown[i]));
  }
  return trees;
}

}  // namespace heliostand
