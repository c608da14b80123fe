// libFuzzer harness: the scenario TOML reader (scenario/scenario.hpp, load_scenario), with stands/tiny's survey
// beside the fuzzed file as survey.csv (so `survey = "survey.csv"` reads a real one). Bad input must end as an
// InputError, never a crash, hang or leak.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "core/input_error.hpp"
#include "scenario/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool survey_placed = [] {
    std::filesystem::copy_file(std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands/tiny/survey.csv",
                               heliostand::fuzz::scratch_folder() / "survey.csv",
                               std::filesystem::copy_options::overwrite_existing);
    return true;
  }();
  (void)survey_placed;
  const auto file = heliostand::fuzz::write_input("scenario.toml", data, size);
  try {
    heliostand::load_scenario(file);
  } catch (const heliostand::InputError&) {
    // refused with a message: the expected end of bad input
  }
  return 0;
}
