#include "batch/batch_manifest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "core/input_error.hpp"
#include "scenario/toml_file.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand {
namespace fs = std::filesystem;

bool is_safe_folder_name(std::string_view name) {
  if (name.empty() || name.size() > 64 || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.';
  });
}

namespace {

// A file named in the manifest, relative to the manifest's folder; must be a readable file.
std::optional<fs::path> existing_file(TomlTableReader& reader, std::string_view key, bool required,
                                      const fs::path& base) {
  const auto text = reader.string(key, required);
  if (!text) return std::nullopt;
  const fs::path path = base / *text;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    reader.problem(key, fmt::format("no such file: {}", path.string()));
    return std::nullopt;
  }
  return path;
}

std::optional<ScenarioLayer> inline_override(TomlTableReader& reader, const fs::path& base) {
  const toml::node* node = reader.node("override");
  if (!node) return std::nullopt;
  if (!node->is_table()) {
    reader.problem("override", fmt::format("expected a table of scenario keys, got {}", toml_type_phrase(*node)));
    return std::nullopt;
  }
  return ScenarioLayer{*node->as_table(), base, reader.key_path("override")};
}

std::optional<ScenarioLayer> scenario_file_layer(TomlTableReader& reader, const fs::path& base) {
  const auto file = existing_file(reader, "file", false, base);
  if (!file) return std::nullopt;
  try {
    return ScenarioLayer{toml::parse_file(file->string()), file->parent_path(), file->string()};
  } catch (const toml::parse_error& error) {
    reader.problems().add(error.source(), reader.key_path("file"),
                          fmt::format("{}:{}: not valid TOML: {}", file->string(), error.source().begin.line,
                                      error.description()));
    return std::nullopt;
  }
}

// The array of tables `key` ([[stand]], [[scenario]]), each read by `read_one`; a name is required and unique.
template <typename Item, typename ReadOne>
std::vector<Item> read_named_tables(TomlTableReader& root, std::string_view key, bool required, ReadOne read_one) {
  std::vector<Item> items;
  const toml::node* node = root.node(key);
  if (!node) {
    if (required) root.problems().add(0, std::string(key), "required: at least one [[" + std::string(key) + "]]");
    return items;
  }
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables()) {
    root.problem(key, fmt::format("expected an array of tables ([[{}]]), got {}", key, toml_type_phrase(*node)));
    return items;
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < array->size(); ++i) {
    TomlTableReader reader(*array->get(i)->as_table(), fmt::format("{}[{}]", key, i + 1), root.problems());
    const auto name = reader.string("name", true);
    if (name && !is_safe_folder_name(*name)) {
      reader.problem("name", fmt::format("'{}' cannot name a folder: use 1-64 letters, digits, '_', '-' or '.' "
                                         "(not '.' or '..')", *name));
    } else if (name && !names.insert(*name).second) {
      reader.problem("name", fmt::format("'{}' is given twice", *name));
    }
    Item item = read_one(reader);
    item.name = name.value_or("");
    reader.report_unknown_keys();
    items.push_back(std::move(item));
  }
  return items;
}

std::vector<std::uint64_t> read_seeds(TomlTableReader& root) {
  std::vector<std::uint64_t> seeds;
  const toml::node* node = root.node("seeds");
  if (!node) {
    root.problems().add(0, "seeds", "required: a list of random seeds, e.g. seeds = [1, 2, 3]");
    return seeds;
  }
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    root.problem("seeds", "expected a non-empty list of integers >= 0");
    return seeds;
  }
  for (const toml::node& element : *array) {
    const auto value = element.value<std::int64_t>();
    if (!element.is_integer() || !value || *value < 0) {
      root.problems().add(element.source(), "seeds", "expected integers >= 0");
      continue;
    }
    const auto seed = static_cast<std::uint64_t>(*value);
    if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end()) {
      root.problems().add(element.source(), "seeds", fmt::format("seed {} is given twice", seed));
      continue;
    }
    seeds.push_back(seed);
  }
  return seeds;
}

}  // namespace

BatchManifest load_batch_manifest(const fs::path& file) {
  const toml::table root_table = read_toml_file(file, file.string(), "batch manifest");
  ScenarioProblems problems(file.string());
  TomlTableReader root(root_table, "", problems);
  const fs::path base = file.parent_path();

  BatchManifest manifest;
  manifest.file = file;
  if (const auto out = root.string("out")) manifest.out = base / *out;
  manifest.seeds = read_seeds(root);
  manifest.write_vtk = root.boolean("vtk").value_or(true);
  manifest.device = root.string("device");
  manifest.override_layer = inline_override(root, base);
  manifest.stands = read_named_tables<BatchStand>(root, "stand", true, [&](TomlTableReader& reader) {
    BatchStand stand;
    stand.scenario_file = existing_file(reader, "scenario", true, base).value_or(fs::path());
    stand.override_layer = inline_override(reader, base);
    return stand;
  });
  manifest.scenarios = read_named_tables<BatchScenario>(root, "scenario", false, [&](TomlTableReader& reader) {
    BatchScenario scenario;
    if (auto layer = scenario_file_layer(reader, base)) scenario.layers.push_back(std::move(*layer));
    if (auto layer = inline_override(reader, base)) scenario.layers.push_back(std::move(*layer));
    return scenario;
  });
  if (manifest.scenarios.empty()) manifest.scenarios.push_back({"as-is", {}});
  root.report_unknown_keys();
  problems.throw_if_any();
  return manifest;
}

}  // namespace heliostand
