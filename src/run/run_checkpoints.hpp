#pragma once
// When a run writes its checkpoints, which run they belong to, and which one a resumed run continues from
// (docs/user-guide.md "Checkpoints and resuming"). The file format is io/checkpoint_file.hpp; the state it
// holds io/checkpoint_state.hpp.
#include <filesystem>
#include <functional>
#include <string>

#include "io/checkpoint_file.hpp"

namespace heliostand {

struct Scenario;

// The newest two are kept: if the newest is found damaged on resume, the one before it still is a way back.
inline constexpr std::size_t checkpoints_kept = 2;

// What a checkpoint must match to be resumed by this run: the program, the build's layout, every input file's
// bytes, and the options that change the outputs (seed, years, device, VTK output).
checkpoint::RunIdentity run_identity(const Scenario& scenario, const std::string& device, bool write_vtk);

// After simulated year `year` (1..years−1) when it is a multiple of `every` (0: never). The last year has
// no checkpoint: the finished outputs replace it.
bool is_checkpoint_year(int year, int every, int years);

// Tries the checkpoints in `folder`, newest first: reads each (checksum, identity) and hands it to `restore`;
// a checkpoint refused by either is reported (file and reason) and the one before it is tried. Returns the
// years done of the one restored; throws CheckpointError listing every refusal when none could be.
int resume_from_newest(const std::filesystem::path& folder, const checkpoint::RunIdentity& identity,
                       const std::function<void(const checkpoint::CheckpointFile&)>& restore);

}  // namespace heliostand
