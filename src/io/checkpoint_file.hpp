#pragma once
// A checkpoint file on disk (docs/formats.md "Checkpoints"): the framing around a payload of run state —
//   magic "HSCHKPT1" | format version (u32) | simulated years done (i32) | run identity (key/value texts)
//   | payload length (u64) | payload | CRC-32 (zlib) of every byte before it
// written atomically (temporary sibling, fsync, rename, fsync of the folder), so a kill at any moment leaves
// either the previous checkpoint or the new one, never half of one. Reading checks, in this order, that the file
// is a checkpoint, of a format this program reads, complete, undamaged, and of this very run (its identity).
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/checkpoint_codec.hpp"

namespace heliostand::checkpoint {

inline constexpr char magic[8] = {'H', 'S', 'C', 'H', 'K', 'P', 'T', '1'};
// Bump when the framing or the payload's layout changes; older checkpoints are then refused as foreign.
inline constexpr std::uint32_t format_version = 1;

// What makes a checkpoint belong to a run: program version, build layout, the bytes of every input file, the
// options that change the outputs. Each entry is compared by name, so a refusal says what differs.
struct RunIdentity {
  std::vector<std::pair<std::string, std::string>> entries;  // e.g. ("scenario file crc32", "1a2b3c4d")

  void add(std::string key, std::string value) { entries.emplace_back(std::move(key), std::move(value)); }
  // Empty when `other` (read from a checkpoint) is this run's; otherwise the first difference, for a message.
  std::string difference_from(const RunIdentity& other) const;
};

struct CheckpointFile {
  int years_done = 0;  // the simulated years the state has completed (year 0 = the established stand)
  RunIdentity identity;
  std::string payload;
};

// "checkpoint_year_0004.hsck" for the state after simulated year 4.
std::string file_name_for_year(int years_done);

// Writes atomically into `folder` under file_name_for_year(file.years_done); returns the path.
std::filesystem::path write_checkpoint(const std::filesystem::path& folder, const CheckpointFile& file);

// Reads and checks one file. Throws CheckpointError with the reason (not a checkpoint, other format version,
// truncated, checksum mismatch, foreign run) when the file cannot be resumed from.
CheckpointFile read_checkpoint(const std::filesystem::path& path, const RunIdentity& expected);

// The checkpoint files in `folder`, newest (most years done) first.
std::vector<std::filesystem::path> checkpoints_in(const std::filesystem::path& folder);

// Deletes all but the newest `keep` checkpoints in `folder`.
void prune_checkpoints(const std::filesystem::path& folder, std::size_t keep);

// The CRC-32 of a file's bytes (zlib), as 8 hex digits: names an input in a RunIdentity.
std::string file_crc32(const std::filesystem::path& path);

// Flushes a file already written (by any stream) to the disk, so a checkpoint never points past what survives
// a crash of the machine.
void sync_file(const std::filesystem::path& path);

}  // namespace heliostand::checkpoint
