// [soil]: the voxel grid under the plot, its initial moisture and nutrient fields, an optional CSV patch
// and the yearly recharge. docs/formats.md lists every key.
//
//   moisture = 0.8                                           # uniform
//   moisture = { gradient = "x", min_face = 1.0, max_face = 0.0 }   # linear along x, y or z
//   moisture = { layer_bottoms_m = [0.3, 0.8], values = [1.0, 0.6] }  # layers by depth
#include <fmt/format.h>

#include <filesystem>

#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

namespace {

std::optional<std::vector<double>> read_numbers(TomlTableReader& reader, std::string_view key, NumberRange range) {
  const toml::node* node = reader.node(key);
  if (!node) return std::nullopt;
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    reader.problem(key, fmt::format("expected a non-empty array of numbers, got {}", toml_type_phrase(*node)));
    return std::nullopt;
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto value = array->get(i)->value<double>();
    if (!value) {
      reader.problem(key, fmt::format("element {}: expected {}", i + 1, range.describe("a number")));
      return std::nullopt;
    }
    if (!range.contains(*value)) {
      reader.problem(key, fmt::format("element {}: {}", i + 1, range.refusal("a number", *value, fmt::format("{}", *value))));
      return std::nullopt;
    }
    values.push_back(*value);
  }
  return values;
}

void read_field(TomlTableReader& reader, std::string_view key, SoilFieldSetting& setting) {
  const toml::node* node = reader.node(key);
  if (!node) return;
  const NumberRange level = between(0.0, 1.0);
  if (auto value = node->value<double>(); value && !node->is_boolean()) {
    if (!level.contains(*value)) reader.problem(key, level.refusal("a number", *value, fmt::format("{}", *value)));
    setting.kind = SoilFieldSetting::Kind::uniform;
    setting.value = *value;
    return;
  }
  const toml::table* table = node->as_table();
  if (!table) {
    reader.problem(key, fmt::format("expected a level 0..1 or an inline table (gradient or layers), got {}",
                                    toml_type_phrase(*node)));
    return;
  }
  TomlTableReader field(*table, reader.key_path(key), reader.problems());
  if (table->contains("gradient")) {
    setting.kind = SoilFieldSetting::Kind::gradient;
    if (auto axis = field.string("gradient")) {
      if (*axis == "x" || *axis == "y" || *axis == "z") {
        setting.axis = (*axis)[0] - 'x';
      } else {
        field.problem("gradient", fmt::format("expected \"x\", \"y\" or \"z\", got \"{}\"", *axis));
      }
    }
    if (auto v = field.number("min_face", level, true)) setting.at_min = *v;
    if (auto v = field.number("max_face", level, true)) setting.at_max = *v;
  } else {
    setting.kind = SoilFieldSetting::Kind::layers;
    auto bottoms = read_numbers(field, "layer_bottoms_m", positive_up_to(limit::soil_depth_m));
    auto values = read_numbers(field, "values", level);
    if (!table->contains("layer_bottoms_m") || !table->contains("values")) {
      reader.problem(key, "an inline table needs either gradient/min_face/max_face or layer_bottoms_m/values");
    } else if (bottoms && values) {
      if (bottoms->size() != values->size())
        field.problem("values", fmt::format("needs one value per layer ({}), got {}", bottoms->size(), values->size()));
      for (std::size_t i = 1; i < bottoms->size(); ++i)
        if ((*bottoms)[i] <= (*bottoms)[i - 1]) {
          field.problem("layer_bottoms_m", "layer bottoms must increase with depth");
          break;
        }
      setting.bottoms_m = *bottoms;
      setting.values = *values;
    }
  }
  field.report_unknown_keys();
}

// The soil grid is allocated whole: a wide plot with the default spacing (no [soil] table) must be refused as surely
// as one with a [soil] table (a 10,000 km plot asked for 2.4e9 voxels and died of std::bad_alloc, or of the OOM
// killer). `line` 0 when there is no table.
constexpr double max_soil_voxels = 5e7;

void check_soil_size(const ScenarioDraft& draft, int line, ScenarioProblems& problems) {
  const auto& roots = draft.scenario.roots;
  if (!draft.plot_valid || !roots.enabled) return;  // no roots: no soil grid
  const auto& plot = draft.scenario.stand.plot;
  const SoilSettings& soil = roots.soil;
  const double cells = std::ceil(plot.width_m() / soil.spacing_m) * std::ceil(plot.depth_m() / soil.spacing_m) *
                       std::ceil(soil.depth_m / soil.spacing_m);
  if (cells > max_soil_voxels)
    problems.add(line, "soil.spacing_m",
                 fmt::format("{:.3g} voxels of {:g} m under the {:g} m x {:g} m plot: too many (at most {:g}); use a "
                             "coarser spacing, or [roots] enabled = false",
                             cells, soil.spacing_m, plot.width_m(), plot.depth_m(), max_soil_voxels));
}

}  // namespace

void parse_soil(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  if (!node) return check_soil_size(draft, 0, problems);
  const toml::table* table = as_table(node, "soil", problems);
  if (!table) return;
  TomlTableReader reader(*table, "soil", problems);
  SoilSettings& soil = draft.scenario.roots.soil;
  if (auto v = reader.number("spacing_m", between(0.05, 5.0))) soil.spacing_m = *v;
  if (auto v = reader.number("depth_m", positive_up_to(limit::soil_depth_m))) soil.depth_m = *v;
  read_field(reader, "moisture", soil.moisture);
  read_field(reader, "nutrient", soil.nutrient);
  if (auto file = reader.string("file")) {
    const std::filesystem::path path = draft.base_dir / *file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      reader.problem("file", fmt::format("no soil file \"{}\"", path.string()));
    } else {
      soil.file = std::filesystem::absolute(path).lexically_normal();
    }
  }
  if (auto v = reader.number("moisture_recharge", between(0.0, 1.0))) soil.recharge.moisture_rate = *v;
  if (auto v = reader.number("nutrient_recharge", between(0.0, 1.0))) soil.recharge.nutrient_rate = *v;
  reader.report_unknown_keys();
  check_soil_size(draft, reader.line_of("spacing_m"), problems);
}

}  // namespace heliostand::scenario_detail
