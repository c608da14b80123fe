#include "batch/batch.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <climits>
#include <thread>

#include "batch/batch_manifest.hpp"
#include "batch/batch_root.hpp"
#include "batch/batch_run.hpp"
#include "batch/batch_summary.hpp"
#include "batch/mpi_ranks.hpp"
#include "batch/run_process.hpp"
#include "batch/worker_pool.hpp"
#include "io/checkpoint_file.hpp"
#include "core/input_error.hpp"
#include "io/output_folder.hpp"

namespace heliostand {
namespace fs = std::filesystem;

namespace {

constexpr int not_run_here = INT_MIN;  // a run's status on the ranks that did not run it (MPI max ignores it)

// How every run of the batch is grown (the batch's options over the manifest's).
struct GrowSettings {
  bool write_vtk = true;
  std::optional<std::string> device;
  int checkpoint_every = 0;  // years; 0: no checkpoints
};

// The child's command line. Paths are relative to the root, where the child runs, so a run's run.json
// (command_line, scenario) is the same wherever the root is and whichever rank ran it. An unfinished run's folder
// (no run.json) holds the marker of its first try: it is grown again with --force, or continued with --resume
// where its first try left a checkpoint (--checkpoint-every), which ends in the same outputs.
std::vector<std::string> grow_arguments(const BatchRun& run, const GrowSettings& settings, bool resume) {
  std::vector<std::string> arguments{"heliostand", "-q", "grow", run.scenario_file().generic_string(),
                                     "--out", run.folder().generic_string(), "--seed", std::to_string(run.seed),
                                     resume ? "--resume" : "--force"};
  if (!settings.write_vtk) arguments.push_back("--no-vtk");
  if (settings.device) arguments.insert(arguments.end(), {"--device", *settings.device});
  if (settings.checkpoint_every > 0)
    arguments.insert(arguments.end(), {"--checkpoint-every", std::to_string(settings.checkpoint_every)});
  return arguments;
}

unsigned default_jobs(const MpiRanks& ranks) {
  // Under MPI the launcher places one rank per core (or per node with -npernode); each rank runs one run at once.
  if (ranks.distributed()) return 1;
  return std::max(1u, std::thread::hardware_concurrency());
}

// Rank 0 takes the root and writes the inputs; the others wait for its verdict, so no rank runs into a
// root that was refused.
void prepare_root_on_first_rank(const MpiRanks& ranks, const fs::path& root, const std::vector<BatchRun>& runs,
                                bool force) {
  std::string refusal;
  if (ranks.rank() == 0) {
    try {
      prepare_batch_root(root, runs, force);
    } catch (const OutputFolderError& e) {
      refusal = e.what();
    }
  }
  if (ranks.broadcast_from_first(refusal.empty() ? 0 : 1) != 0) {
    throw OutputFolderError(ranks.rank() == 0 ? refusal : "the output folder was refused (see rank 0)");
  }
}

std::vector<int> run_my_share(const MpiRanks& ranks, const fs::path& root, const std::vector<BatchRun>& runs,
                              unsigned jobs, const GrowSettings& settings) {
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(ranks.size())) == ranks.rank()) mine.push_back(i);
  }
  std::vector<int> statuses(runs.size(), not_run_here);
  const fs::path program = own_executable();
  const std::string label = ranks.distributed() ? fmt::format("rank {}: ", ranks.rank()) : "";
  run_worker_pool(mine.size(), jobs, label, [&](std::size_t k) {
    const BatchRun& run = runs[mine[k]];
    if (run_finished(root, run)) {
      statuses[mine[k]] = 0;
      return JobReport{run.id(), true, "finished earlier, kept"};
    }
    const bool resume = settings.checkpoint_every > 0 && !checkpoint::checkpoints_in(root / run.folder()).empty();
    const ProcessOutcome outcome =
        run_process(program, grow_arguments(run, settings, resume), root, root / run.log_file());
    statuses[mine[k]] = outcome.exit_status;
    return JobReport{run.id(), outcome.exit_status == 0,
                     outcome.exit_status == 0 ? fmt::format("in {}", human_duration(outcome.seconds)) : outcome.error};
  });
  return statuses;
}

}  // namespace

int run_batch(const BatchOptions& options) {
  MpiRanks ranks;
  const BatchManifest manifest = load_batch_manifest(options.manifest);
  const fs::path root = fs::absolute(options.out.value_or(manifest.out)).lexically_normal();
  if (root.empty() || (!options.out && manifest.out.empty())) {
    throw InputError({{options.manifest.string(), 0, "out", "no output folder: give `out` or --out"}}, "key");
  }
  const std::vector<BatchRun> runs = list_batch_runs(manifest);
  prepare_root_on_first_rank(ranks, root, runs, options.force);
  ranks.barrier();

  const unsigned jobs = options.jobs > 0 ? options.jobs : default_jobs(ranks);
  if (ranks.rank() == 0) {
    spdlog::info("batch {}: {} runs ({} stands x {} scenarios x {} seeds) on {} rank(s) x {} job(s) -> {}",
                 options.manifest.string(), runs.size(), manifest.stands.size(), manifest.scenarios.size(),
                 manifest.seeds.size(), ranks.size(), jobs, root.string());
  }
  const GrowSettings settings{manifest.write_vtk && !options.no_vtk, options.device ? options.device : manifest.device,
                              options.checkpoint_every};
  std::vector<int> statuses = run_my_share(ranks, root, runs, jobs, settings);
  ranks.max_over_ranks(statuses);

  const std::size_t failed = static_cast<std::size_t>(std::count_if(statuses.begin(), statuses.end(), [](int s) { return s != 0; }));
  if (ranks.rank() == 0) {
    std::vector<RunResult> results;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      // A run no rank could start (its job threw before the process ran) is reported as not run.
      results.push_back({&runs[i], statuses[i],
                         statuses[i] == not_run_here ? "not run: the batch could not start it (see its log above)"
                                                     : failure_reason(statuses[i], root / runs[i].log_file())});
    }
    write_batch_summary(root, results);
    if (failed == 0) {
      spdlog::info("all {} runs finished; summary: {}", runs.size(), (root / "summary.csv").string());
    } else {
      spdlog::error("{} of {} runs failed (their errors: {}); the others finished", failed, runs.size(),
                    (root / "summary.csv").string());
    }
  }
  return failed == 0 ? 0 : 1;
}

}  // namespace heliostand
