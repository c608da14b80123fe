// [[hollow]]: a hollow on a surveyed tree (docs/formats.md). Keys are HollowSpec's fields; only the tree,
// the height and the azimuth are required. Ranges that need the trunk (wider than the stem, above the
// tree top) are checked once the survey is read (attach_hollows_to_survey).
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {
namespace {

std::optional<std::string> read_tree_id(TomlTableReader& reader) {
  const toml::node* node = reader.node("tree");
  if (!node) {
    reader.problems().add(reader.line(), reader.key_path("tree"), "required key missing (the survey id of the tree)");
    return std::nullopt;
  }
  if (auto text = node->value_exact<std::string>()) return *text;
  if (auto number = node->value_exact<std::int64_t>()) return std::to_string(*number);
  reader.problem("tree", fmt::format("expected a tree id (string or integer), got {}", toml_type_phrase(*node)));
  return std::nullopt;
}

void read_sizes(TomlTableReader& reader, hollow::HollowSpec& spec) {
  struct Size {
    const char* key;
    double hollow::HollowSpec::*field;
  };
  // Lower bounds, and the thickest stem as a common upper one: the exact upper bounds depend on W and on the trunk,
  // and validate() states them once the survey is read.
  static const Size sizes[] = {
      {"width_m", &hollow::HollowSpec::width_m},
      {"wound_height_m", &hollow::HollowSpec::wound_height_m},
      {"callus_radius_m", &hollow::HollowSpec::callus_radius_m},
      {"bark_line_spacing_m", &hollow::HollowSpec::bark_line_spacing_m},
      {"bark_segment_m", &hollow::HollowSpec::bark_segment_m},
      {"outline_step_m", &hollow::HollowSpec::outline_step_m},
      {"surface_tolerance_m", &hollow::HollowSpec::surface_tolerance_m},
  };
  for (const Size& size : sizes)
    if (auto value = reader.number(size.key, positive_up_to(limit::stem_width_m))) spec.*size.field = *value;
  if (auto bulge = reader.number("bulge_m", non_negative_up_to(limit::stem_width_m))) spec.bulge_m = *bulge;
  if (auto corners = reader.integer("polygon_corners", between(4, 36))) spec.polygon_corners = static_cast<int>(*corners);
}

constexpr NamedChoices<hollow::Placement, 2> placement_names{
    {{hollow::Placement::cylindrical, "cylindrical"}, {hollow::Placement::tangent_plane, "tangent_plane"}}};

void read_placement(TomlTableReader& reader, hollow::HollowSpec& spec) {
  if (auto placement = reader.choice("placement", placement_names)) spec.placement = *placement;
}

void parse_one(const toml::table& table, const std::string& path, ScenarioDraft& draft, ScenarioProblems& problems) {
  TomlTableReader reader(table, path, problems);
  ScenarioDraft::ScenarioHollow entry;
  const auto tree = read_tree_id(reader);
  entry.tree_line = reader.line_of("tree");
  TreeHollow& hollow = entry.hollow;
  if (auto height = reader.number("height_m", non_negative_up_to(limit::tree_height), true)) hollow.spec.height_m = *height;
  if (auto azimuth = reader.number("azimuth_deg", between(-360.0, 360.0), true)) hollow.spec.azimuth_deg = *azimuth;
  read_sizes(reader, hollow.spec);
  read_placement(reader, hollow.spec);
  if (auto seed = reader.integer("seed", any_seed())) {
    hollow.spec.seed = static_cast<std::uint64_t>(*seed);
    hollow.seed_given = true;
  }
  reader.report_unknown_keys();
  if (!tree) return;
  entry.tree_id = *tree;
  hollow.file = problems.file();
  hollow.line = reader.line();
  hollow.field = path;
  hollow.field_kind = "key";
  draft.hollows.push_back(std::move(entry));
}

}  // namespace

void parse_hollow(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  for_each_table_of_array(node, "hollow", problems,
                          [&](const toml::table& table, const std::string& path) { parse_one(table, path, draft, problems); });
}

void attach_hollows_to_survey(ScenarioDraft& draft, ScenarioProblems& problems) {
  Scenario& scenario = draft.scenario;
  std::map<std::string, SurveyRecord*> by_id;
  for (auto& tree : scenario.survey.trees) by_id.emplace(tree.id, &tree);
  std::vector<SurveyRecord*> received;  // in the order of their first [[hollow]]
  for (auto& entry : draft.hollows) {
    auto it = by_id.find(entry.tree_id);
    if (it == by_id.end()) {
      problems.add(entry.tree_line, entry.hollow.field + ".tree",
                   fmt::format("tree id \"{}\" is not in the survey", entry.tree_id));
      continue;
    }
    if (std::find(received.begin(), received.end(), it->second) == received.end()) received.push_back(it->second);
    it->second->hollows.push_back(std::move(entry.hollow));
  }
  // The trees that received scenario hollows, checked with all their hollows. The survey's own hollows passed
  // the survey reader alone (else the survey was rejected and nothing is attached), so every problem here is
  // new — a clash may land on a survey hollow, which keeps its own file, line and column.
  for (SurveyRecord* tree : received) {
    const auto found = check_tree_hollows(*tree, scenario.species_of(*tree));
    if (!found.empty()) problems.merge(InputError(found, "key"));
  }
}

}  // namespace heliostand::scenario_detail
