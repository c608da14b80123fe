#include "run/run_checkpoints.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "io/checkpoint_state.hpp"
#include "io/output_folder.hpp"
#include "scenario/scenario.hpp"

namespace heliostand {

checkpoint::RunIdentity run_identity(const Scenario& scenario, const std::string& device, bool write_vtk) {
  checkpoint::RunIdentity identity;
  identity.add("heliostand version", HELIOSTAND_VERSION);
  identity.add("checkpoint layout", checkpoint::layout_fingerprint());
  identity.add("scenario file CRC-32", checkpoint::file_crc32(scenario.file));
  identity.add("survey file CRC-32", checkpoint::file_crc32(scenario.survey.file));
  identity.add("soil file CRC-32", scenario.roots.soil.file ? checkpoint::file_crc32(*scenario.roots.soil.file) : "none");
  identity.add("seed", std::to_string(scenario.run.seed));
  identity.add("years", std::to_string(scenario.run.years));
  identity.add("device", device);
  identity.add("VTK output", write_vtk ? "on" : "off");
  return identity;
}

bool is_checkpoint_year(int year, int every, int years) { return every > 0 && year > 0 && year < years && year % every == 0; }

int resume_from_newest(const std::filesystem::path& folder, const checkpoint::RunIdentity& identity,
                       const std::function<void(const checkpoint::CheckpointFile&)>& restore) {
  std::string refused;
  for (const auto& path : checkpoint::checkpoints_in(folder)) {
    try {
      const checkpoint::CheckpointFile file = checkpoint::read_checkpoint(path, identity);
      restore(file);
      spdlog::info("resuming from {} ({} simulated years done)", path.string(), file.years_done);
      return file.years_done;
    } catch (const checkpoint::CheckpointError& e) {
      spdlog::warn("checkpoint {} refused: it {}", path.string(), e.what());
      refused += fmt::format("\n  {}: it {}", path.string(), e.what());
    } catch (const OutputFolderError& e) {
      spdlog::warn("checkpoint {} refused: {}", path.string(), e.what());
      refused += fmt::format("\n  {}: {}", path.string(), e.what());
    }
  }
  throw checkpoint::CheckpointError(fmt::format(
      "cannot resume the run in {}: {}; start it over with --force instead of --resume", folder.string(),
      refused.empty() ? "it holds no checkpoint (checkpoint_year_NNNN.hsck)" : "no checkpoint can be used:" + refused));
}

}  // namespace heliostand
