// heliostand batch MANIFEST: grow every stand × scenario × seed of a manifest (batch/batch.hpp).
#include "batch/batch.hpp"
#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "cli/path_checks.hpp"

namespace heliostand::cli {

void add_batch_command(CLI::App& app, int& status) {
  auto* command = app.add_subcommand(
      "batch", "Grow every stand x scenario x seed of a manifest, each run in its own folder; under mpirun/srun "
               "the runs are spread over the ranks");
  auto options = std::make_shared<BatchOptions>();
  auto manifest = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto device = std::make_shared<std::string>();
  command->add_option("manifest", *manifest, "Batch manifest TOML")->required();
  command->add_option("-o,--out", *out, "Output root (overrides the manifest's `out`)")->check(path_check("folder"));
  command->add_option("-j,--jobs", options->jobs, "Runs at once (per MPI rank); default: the cores, 1 under MPI")
      ->check(whole_number_check());
  command->add_flag("-f,--force", options->force, "Delete an earlier batch in the output root and start over");
  command->add_flag("--no-vtk", options->no_vtk, "Write the tables only");
  command->add_option("--device", *device, "Device of every run (overrides the manifest and the scenarios)");
  command->add_option("--checkpoint-every", options->checkpoint_every,
                      "Each run writes a checkpoint after every N years; the batch started again resumes its "
                      "unfinished runs from them (grow --resume) instead of growing them anew")
      ->check(whole_number_check());
  command->callback([=, &status] {
    options->manifest = *manifest;
    if (!out->empty()) options->out = *out;
    if (!device->empty()) options->device = *device;
    status = report_errors([&] { return run_batch(*options); });
  });
}

}  // namespace heliostand::cli
