#pragma once
// `heliostand bench light --stand SCENARIO`: the scenario's stand established as `heliostand grow` establishes it
// (survey read, every tree calibrated and grown to its surveyed age; no simulated year), handed to the light
// benchmark as what the light solver sees of it: every living tree's leaf balls and the scenario's [light] with
// the plot as the light domain (run/simulation.cpp does the same for the stand's solver).
#include <string>

#include "light/light_benchmark.hpp"

namespace heliostand {

struct Scenario;

// `scenario` as load_scenario read it (a bad scenario or survey is refused there, with file, line, field and reason),
// its [light] as the benchmark lights it, under `name` (the scenario file as the user gave it). Throws InputError where
// `grow` would refuse the stand as beyond this machine's memory (stand/memory_estimate.hpp).
LightBenchmarkStand established_canopy(const Scenario& scenario, const std::string& name);

}  // namespace heliostand
