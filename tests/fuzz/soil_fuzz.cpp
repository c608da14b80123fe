// libFuzzer harness: the soil file reader (roots/soil_file.hpp) on a 4 x 4 x 3-cell grid. Bad input must end as
// an InputError, never a crash, hang or leak.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "core/input_error.hpp"
#include "roots/soil_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  heliostand::roots::SoilGridGeometry geometry;
  geometry.spacing_m = 0.5;
  geometry.cells = {4, 4, 3};
  heliostand::roots::SoilGrid soil(geometry, 1.0, 1.0);
  const auto file = heliostand::fuzz::write_input("soil.csv", data, size);
  try {
    heliostand::roots::read_soil_csv(file, soil);
  } catch (const heliostand::InputError&) {
    // refused with a message: the expected end of bad input
  }
  return 0;
}
