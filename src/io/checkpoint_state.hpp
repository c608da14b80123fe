#pragma once
// The run state a checkpoint holds, as its payload (docs/formats.md "Checkpoints"): everything a simulated year
// hands to the next and everything the outputs have accumulated, so that a resumed run writes byte for byte what
// the uninterrupted run writes. The random streams need no state of their own: every draw comes from a stream
// derived afresh from the run seed and tags (rng/random_stream.hpp), so the trees' ids, ages and axis ids carry
// them. What the scenario fixes (species and root parameters, thinning schedule, soil settings) is taken from the
// scenario on resume, which the checkpoint's run identity proves to be the same.
#include <string>
#include <string_view>

#include "io/run_manifest.hpp"

namespace heliostand {

struct Scenario;
class Stand;
class RootZone;
class StandOutput;
class StandYear;
class StageClock;

namespace checkpoint {

// What the run loop itself carries besides its objects.
struct RunProgress {
  long tree_years = 0;
  double wall_seconds = 0;   // the run's up to the checkpoint, every earlier session's included
  std::string started_utc;   // of the run as first started: run.json keeps it
  std::string command_line;  // likewise: the command that reproduces the outputs
};

// The parts of a run, as run_simulation() holds them; `roots` null when the scenario has no roots.
struct RunParts {
  Stand& stand;
  RootZone* roots;
  StandOutput& output;
  StandYear& year;
  StageClock& clock;
  RunProgress& progress;
};

// Also flushes the output tables to the disk: the checkpoint counts their rows.
std::string save_run(const RunParts& run);

// Restores `run` from a payload. The parts must be built as for a fresh run of `scenario`, but not established:
// the stand without trees, the root zone not spun up, the output folder opened for resuming. Throws CheckpointError
// when the payload does not fit the scenario or ends early.
void load_run(std::string_view payload, const Scenario& scenario, const RunParts& run);

// The sizes of the structs the payload holds as raw bytes, for the run identity.
std::string layout_fingerprint();

}  // namespace checkpoint
}  // namespace heliostand
