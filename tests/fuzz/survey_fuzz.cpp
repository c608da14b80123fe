// libFuzzer harness: the survey CSV reader (survey/read_survey.hpp) under the stand of stands/tiny (its plot,
// species and age). Bad input must end as an InputError, never a crash, hang or leak.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "core/input_error.hpp"
#include "scenario/scenario.hpp"
#include "survey/read_survey.hpp"

namespace {

heliostand::SurveyReadOptions tiny_stand_options() {
  const heliostand::Scenario tiny =
      heliostand::load_scenario(std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands/tiny/scenario.toml");
  heliostand::SurveyReadOptions options;
  options.plot = tiny.stand.plot;
  options.stand_age_years = tiny.stand.age_at_survey_years;
  options.species = tiny.species;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const heliostand::SurveyReadOptions options = tiny_stand_options();
  const auto file = heliostand::fuzz::write_input("survey.csv", data, size);
  try {
    heliostand::read_survey(file, options);
  } catch (const heliostand::InputError&) {
    // refused with a message: the expected end of bad input
  }
  return 0;
}
