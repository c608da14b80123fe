#include "run/stand_benchmark.hpp"

#include <malloc.h>
#include <sys/resource.h>

#include <cstdlib>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "core/json_text.hpp"
#include "core/page_settings.hpp"
#include "core/processor.hpp"
#include "run/simulation.hpp"
#include "scenario/scenario.hpp"
#include "stand/memory_estimate.hpp"

namespace heliostand {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary directory, removed with this object.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string name = (fs::temp_directory_path() / "heliostand-bench-XXXXXX").string();
    if (::mkdtemp(name.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder for the tables");
    path_ = name;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Bytes the program holds on the heap now (glibc's mallinfo2, every arena, mmapped blocks included).
std::size_t heap_in_use_bytes() {
  const struct mallinfo2 heap = ::mallinfo2();
  return heap.uordblks + heap.hblkhd;
}

nlohmann::ordered_json stage_object(const std::vector<std::pair<std::string, double>>& stage_seconds) {
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  for (const auto& [stage, seconds] : stage_seconds) stages[stage] = seconds;
  return stages;
}

nlohmann::ordered_json light_parts(double search, double far_field, double shading) {
  return {{"search", search}, {"far_field", far_field}, {"shading", shading}};
}

// Each year's cost, in the order simulated: how the time per year grows with the stand (docs/performance.md).
nlohmann::ordered_json by_year(const std::vector<YearCost>& years) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const YearCost& year : years)
    list.push_back({{"year", year.year},
                    {"stand_age", year.stand_age},
                    {"trees_alive", year.trees_alive},
                    {"stage_seconds", stage_object(year.stage_seconds)},
                    {"stage_cpu_seconds", stage_object(year.stage_cpu_seconds)},
                    {"light_parts_seconds",
                     light_parts(year.light_search_seconds, year.light_far_field_seconds, year.light_shading_seconds)},
                    {"light_tile_candidates_per_ball", year.light_tile_candidates_per_ball}});
  return list;
}

// The operating system's part in the run (system_part_so_far); null where the account cannot be read.
void add_system_part(nlohmann::ordered_json& json) {
  const auto part = system_part_so_far();
  json["system_cpu_seconds"] = part ? nlohmann::ordered_json(part->cpu_seconds) : nlohmann::ordered_json(nullptr);
  json["minor_page_faults"] = part ? nlohmann::ordered_json(part->minor_page_faults) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json report(const Scenario& scenario, const SimulationSummary& run, std::size_t heap_at_end) {
  const std::size_t peak = peak_resident_bytes();
  const std::size_t trees = scenario.survey.trees.size();
  nlohmann::ordered_json json;
  json["benchmark"] = "stand";
  json["scenario"] = scenario.file.string();
  json["device"] = run.device;
  json["hardware_threads"] = std::thread::hardware_concurrency();  // the cores stage_cpu_seconds can fill
  json["processor"] = processor_json(this_processor());  // the machine the seconds are of
  json["pages"] = page_settings_json(this_process_page_settings());  // and the allocator's settings
  json["seed"] = scenario.run.seed;
  json["vtk_output"] = false;
  json["years"] = run.last_stand_age - run.first_stand_age;
  json["first_stand_age"] = run.first_stand_age;
  json["last_stand_age"] = run.last_stand_age;
  json["trees"] = trees;
  json["trees_alive_at_end"] = run.trees_alive;
  json["trees_removed"] = run.trees_removed;
  json["trees_dead"] = run.trees_dead;
  json["tree_years"] = run.tree_years;
  json["stage_seconds"] = stage_object(run.stage_seconds);
  json["stage_cpu_seconds"] = stage_object(run.stage_cpu_seconds);
  json["total_seconds"] = run.wall_seconds;
  json["tree_years_per_second"] = run.wall_seconds > 0 ? run.tree_years / run.wall_seconds : 0.0;
  json["leaf_balls_at_end"] = run.leaf_balls;
  json["shoots_at_end"] = run.shoots;
  json["root_segments_at_end"] = run.root_segments;
  json["light_tile_candidates_per_ball"] = run.light_tile_candidates_per_ball;
  json["light_far_field_cell_m_max"] = run.light_far_field_cell_m_max;
  json["light_parts_seconds"] = light_parts(run.light_search_seconds, run.light_far_field_seconds,
                                            run.light_shading_seconds);
  json["heap_in_use_at_end_bytes"] = heap_at_end;
  json["peak_memory_bytes"] = peak;
  json["peak_memory_mib"] = static_cast<double>(peak) / (1024.0 * 1024.0);
  add_system_part(json);
  json["by_year"] = by_year(run.by_year);
  return json;
}

}  // namespace

std::size_t peak_resident_bytes() {
  rusage usage{};
  if (::getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

std::optional<SystemPart> system_part_so_far() {
  rusage usage{};
  if (::getrusage(RUSAGE_SELF, &usage) != 0) return std::nullopt;
  return SystemPart{static_cast<double>(usage.ru_stime.tv_sec) + static_cast<double>(usage.ru_stime.tv_usec) * 1e-6,
                    usage.ru_minflt};
}

Scenario stand_benchmark_scenario(const StandBenchmarkOptions& options) {
  Scenario scenario = load_scenario(options.scenario);
  if (options.seed) scenario.set_seed(*options.seed);
  if (options.years) scenario.set_years(*options.years);
  for (const auto& warning : scenario.survey.warnings) spdlog::warn("{}", warning);
  refuse_run_beyond_this_machine(scenario);  // as `grow` does: before the tables' folder is made
  return scenario;
}

std::string run_stand_benchmark(const Scenario& scenario, const StandBenchmarkOptions& options) {
  std::optional<ScratchFolder> scratch;
  if (options.tables_folder.empty()) scratch.emplace();
  SimulationOptions run;
  run.output_folder = scratch ? scratch->path() : options.tables_folder;
  run.force = options.force;
  run.device = options.device;
  run.write_vtk = false;
  run.command_line = options.command_line;
  // The heap after the last year, while the stand is still held: what the grown trees and roots cost to keep.
  std::size_t heap_at_end = 0;
  run.observe_year = [&](const Stand&, int year) {
    if (year == scenario.run.years) heap_at_end = heap_in_use_bytes();
  };
  const SimulationSummary summary = run_simulation(scenario, run);
  return json_text(report(scenario, summary, heap_at_end));
}

}  // namespace heliostand
