#include "experiments/kanamaru/kanamaru_scenario.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "architecture/crown_metrics.hpp"
#include "core/seconds_since.hpp"
#include "geometry/angles.hpp"
#include "io/csv_writer.hpp"
#include "io/dichotomy_tree_vtk.hpp"
#include "io/output_folder.hpp"
#include "io/pvd_collection.hpp"
#include "rng/random_stream.hpp"
#include "scenario/toml_file.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand {

KanamaruScenario load_kanamaru_scenario(const std::filesystem::path& file) {
  ScenarioProblems problems(file.string());
  KanamaruScenario s;
  s.file = file;
  const toml::table root = read_toml_file(file, file.string(), "scenario");
  TomlTableReader top(root, "", problems);
  const toml::node* model_node = top.node("model");
  top.report_unknown_keys();
  const toml::table* model = model_node ? model_node->as_table() : nullptr;
  if (!model) {
    problems.add(1, "model", "expected a [model] table");
    problems.throw_if_any();
  }
  TomlTableReader r(*model, "model", problems);
  if (auto kind = r.string("kind")) {
    if (*kind == "dichotomy" || *kind == "two_trees" || *kind == "bud_sphere" || *kind == "bud_clusters" ||
        *kind == "bud_cylinder")
      s.kind = *kind;
    else
      r.problem("kind", fmt::format("expected dichotomy, two_trees, bud_sphere, bud_clusters or bud_cylinder, "
                                    "got \"{}\"", *kind));
  }
  KanamaruParameters& p = s.parameters;
  auto integer = [&](const char* key, int& target, NumberRange range) {
    if (auto v = r.integer(key, range)) target = static_cast<int>(*v);
  };
  auto number = [&](const char* key, double& target, NumberRange range) {
    if (auto v = r.number(key, range)) target = *v;
  };
  integer("generations", p.generations, between(0, 200));
  number("heliotropism", p.heliotropism, between(0.0, 1.0));
  number("leaf_ball_radius", p.leaf_ball_radius, positive());
  number("death_threshold", p.death.standard, any_number());
  number("death_threshold_dither", p.death.dither, non_negative());
  number("branching_angle_deg", p.branching_angle_deg, between(0.0, 90.0));
  number("intensity_ratio", p.light.intensity_ratio, positive());
  number("transmittance", p.light.transmittance, {0.0, 1.0, true, false});
  integer("sky_bands", p.light.sky_bands, between(2, 64));
  integer("sky_sectors", p.light.sky_sectors, between(1, 128));
  if (p.light.sky_bands % 2) r.problem("sky_bands", "expected an even number");
  if (auto pruning = r.string("pruning")) {
    if (*pruning == "light") p.pruning = Pruning::light;
    else if (*pruning == "random") p.pruning = Pruning::random;
    else if (*pruning == "none") p.pruning = Pruning::none;
    else r.problem("pruning", fmt::format("expected light, random or none, got \"{}\"", *pruning));
  }
  number("random_survival", p.random_survival, between(0.0, 1.0));
  if (auto seed = r.integer("seed", non_negative())) s.seed = static_cast<std::uint64_t>(*seed);
  number("root_length", s.root_length, positive());
  number("tree_spacing", s.tree_spacing, positive());
  integer("remove_left_after", s.remove_left_after, at_least(-1));
  integer("buds", s.buds, between(1, 10000));
  number("bud_radius", s.bud_radius, positive());
  integer("latest_sprouting", s.latest_sprouting, between(1, 200));
  integer("clusters", s.clusters, between(1, 100));
  number("cluster_spread", s.cluster_spread, non_negative());
  number("cylinder_height", s.cylinder_height, positive());
  number("cylinder_radius", s.cylinder_radius, positive());
  integer("output_interval", s.output_interval, between(1, 1000));
  r.report_unknown_keys();
  problems.throw_if_any();
  return s;
}

std::vector<BudStart> starts_of(const KanamaruScenario& s) {
  if (s.kind == "dichotomy") return {root_branch({0.0, 0.0, 0.0}, s.root_length)};
  if (s.kind == "two_trees")
    return {root_branch({-0.5 * s.tree_spacing, 0.0, 0.0}, s.root_length, 0),
            root_branch({0.5 * s.tree_spacing, 0.0, 0.0}, s.root_length, 1)};
  if (s.kind == "bud_sphere")
    return bud_sphere({{0.0, 0.0, s.bud_radius}, s.bud_radius, s.buds, s.latest_sprouting}, s.seed);
  if (s.kind == "bud_cylinder")
    return bud_cylinder({{0.0, 0.0, 0.0}, s.cylinder_radius, s.cylinder_height, s.buds, s.latest_sprouting},
                        s.seed);
  // bud_clusters: cluster centres in a disc, buds split evenly among them.
  RandomStream random(s.seed, {0xC1u});
  std::vector<BudStart> all;
  for (int c = 0; c < s.clusters; ++c) {
    const double r = s.cluster_spread * std::sqrt(random.uniform()), a = random.uniform(0.0, 2.0 * pi);
    const glm::dvec3 centre{r * std::cos(a), r * std::sin(a), s.bud_radius + random.uniform() * s.bud_radius};
    const int buds = s.buds / s.clusters + (c < s.buds % s.clusters);
    auto cluster = bud_sphere({centre, s.bud_radius, buds, s.latest_sprouting}, s.seed, c);
    all.insert(all.end(), cluster.begin(), cluster.end());
  }
  return all;
}

KanamaruRunSummary run_kanamaru(const KanamaruScenario& s, const std::filesystem::path& out, bool force) {
  const auto started = std::chrono::steady_clock::now();
  OutputFolder folder(out, force);  // a new or empty folder, or with `force` an earlier heliostand output
  DichotomyTree tree(starts_of(s), s.parameters.branching_angle_deg, s.seed);
  KanamaruGrowth growth(s.parameters, s.seed);
  PvdCollection pvd;
  auto snapshot = [&](const DichotomyTree& t) {
    const std::string name = fmt::format("crown_gen_{:04d}.vtp", t.generation());
    write_crown_vtp(t, s.parameters.leaf_ball_radius, folder.path_of(name));
    folder.record_output(name);
    pvd.add(t.generation(), name);
  };
  snapshot(tree);
  growth.grow(tree, s.parameters.generations, [&](const DichotomyTree& t) {
    if (t.generation() == s.remove_left_after) tree.remove_group(0);
    if (t.generation() % s.output_interval == 0 || t.generation() == s.parameters.generations) snapshot(t);
  });
  folder.write_file("crown.pvd", pvd.to_xml());

  std::ostringstream generations;
  CsvWriter g(generations);
  g.header({"generation", "added", "survived", "mean_light"});
  for (const auto& record : growth.history())
    g.integer(record.generation).integer(record.added).integer(record.survived).number(record.mean_light, 4).end_row();
  folder.write_file("generations.csv", generations.str());

  std::ostringstream tips;
  CsvWriter t(tips);
  t.header({"group", "x", "y", "z", "dx", "dy", "dz"});
  for (int i : tree.tips()) {
    const auto& b = tree.branches()[i];
    const glm::dvec3 d = tree.direction(i);
    t.integer(b.group).number(b.tip.x, 4).number(b.tip.y, 4).number(b.tip.z, 4);
    t.number(d.x, 4).number(d.y, 4).number(d.z, 4).end_row();
  }
  folder.write_file("tips.csv", tips.str());
  KanamaruRunSummary summary;
  summary.generations = tree.generation();
  summary.tips = static_cast<int>(tree.tips().size());
  for (const auto& b : tree.branches()) summary.living_branches += b.alive;
  summary.seconds = seconds_since(started);
  return summary;
}

}  // namespace heliostand
