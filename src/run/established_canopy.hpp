#pragma once
// `heliostand bench light --stand SCENARIO`: the scenario's stand established as `heliostand grow` establishes it
// (survey read, every tree calibrated and grown to its surveyed age; no simulated year), handed to the light
// benchmark as what the light solver sees of it: every living tree's leaf balls and the scenario's [light] with
// the plot as the light domain (run/simulation.cpp does the same for the stand's solver).
#include <filesystem>

#include "light/light_benchmark.hpp"

namespace heliostand {

// Throws InputError (file, line, field, reason) for a missing or bad scenario or survey.
LightBenchmarkStand established_canopy(const std::filesystem::path& scenario_file);

}  // namespace heliostand
