#pragma once
// A scenario: which stand to grow, for how long, with which species and light parameters, and which
// thinnings — everything resolved and checked (docs/formats.md, "Scenario TOML").
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "architecture/species.hpp"
#include "compute/device_choice.hpp"
#include "geometry/plot_bounds.hpp"
#include "light/light_parameters.hpp"
#include "scenario/competition_settings.hpp"
#include "scenario/output_detail.hpp"
#include "scenario/roots_settings.hpp"
#include "scenario/thinning_event.hpp"
#include "scenario/vtk_compression.hpp"
#include "survey/survey.hpp"
#include "survey/survey_format.hpp"

namespace heliostand {

struct StandSettings {
  std::filesystem::path survey_file;  // absolute
  int age_at_survey_years = 0;
  PlotBounds plot;                    // given, or the survey's extent widened by plot_margin_m
  std::optional<double> plot_margin_m;  // set when the plot is taken from the survey's stem positions
  std::string default_species;        // species of survey records that name none
  SurveyFormat survey_format;         // separator, column units, multi-stemmed trees
};

struct RunSettings {
  int years = 0;                      // years to simulate after the survey
  std::uint64_t seed = 1;
  int output_interval_years = 1;      // write the stand every this many years (and at the start and end)
  OutputDetail output_detail = default_output_detail;  // what the VTK blocks draw of each tree
  VtkCompression vtk_compression = default_vtk_compression;  // how the VTK pieces are compressed
  int roots_output_interval_years = 1;  // roots and soil blocks in output years at multiples of this age; 0 never
  compute::DeviceChoice device;
};

struct Scenario {
  std::filesystem::path file;  // absolute
  StandSettings stand;
  RunSettings run;
  std::map<std::string, SpeciesParameters> species;  // by name; SpeciesParameters::name = the key
  LightParameters light;
  CompetitionSettings competition;      // [competition]
  // Fixed-age events sorted by age (file order among equal ages), then the triggered ones in file order.
  // ThinningEvent::scenario_order keeps the file order, in which the events of one year are applied.
  std::vector<ThinningEvent> thinning;
  RootsSettings roots;                  // [roots], [soil], [coupling], [[root_pruning]]
  Survey survey;                        // read, checked and imputed; its warnings are for the caller to log

  double plot_area_ha() const { return stand.plot.area_ha(); }
  int final_age_years() const { return stand.age_at_survey_years + run.years; }
  const SpeciesParameters& species_of(const SurveyRecord& tree) const { return species.at(tree.species); }
  // The stand solver's light: [light] with its periodic domain, which the reader sets to the surveyed plot unless
  // [light] gives plot_x_min .. plot_y_max. A scenario built in code without a domain gets the plot.
  LightParameters stand_light() const {
    LightParameters resolved = light;
    if (resolved.plot_x_max <= resolved.plot_x_min || resolved.plot_y_max <= resolved.plot_y_min) {
      resolved.plot_x_min = stand.plot.x_min;
      resolved.plot_y_min = stand.plot.y_min;
      resolved.plot_x_max = stand.plot.x_max;
      resolved.plot_y_max = stand.plot.y_max;
    }
    return resolved;
  }

  // Command-line overrides (--years, --seed). A shorter run must still contain every thinning: otherwise
  // InputError naming the thinning's line and key 'run.years'.
  void set_years(int years);
  void set_seed(std::uint64_t seed) { run.seed = seed; }
};

// Parses the scenario, reads its survey, and checks them against each other. Throws InputError
// (field kind "key"; survey problems keep "column") listing every problem found.
Scenario load_scenario(const std::filesystem::path& file);

}  // namespace heliostand
