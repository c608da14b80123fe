#pragma once
// A batch manifest (TOML): which stands are grown under which scenarios with which seeds, and where the
// outputs go. Every run is one stand × one scenario × one seed. Format: docs/formats.md "Batch manifest".
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace heliostand {

// A TOML layer merged over a run's scenario: a file of scenario tables, or an inline `override` table.
// Relative paths in it (stand.survey, soil.file) are relative to `base_folder`.
struct ScenarioLayer {
  toml::table table;
  std::filesystem::path base_folder;
  std::string origin;  // where it came from, for messages ("batch.toml: stand[1].override")
};

struct BatchStand {
  std::string name;                      // a folder name: letters, digits, '_', '-', '.'
  std::filesystem::path scenario_file;   // a complete scenario: survey, plot, species, defaults
  std::optional<ScenarioLayer> override_layer;
};

struct BatchScenario {
  std::string name;
  std::vector<ScenarioLayer> layers;     // its file, then its inline override (either may be absent)
};

struct BatchManifest {
  std::filesystem::path file;
  std::filesystem::path out;             // the output root; relative paths are relative to the manifest
  std::vector<std::uint64_t> seeds;
  std::vector<BatchStand> stands;
  std::vector<BatchScenario> scenarios;  // none given: one scenario "as-is", the stand's scenario unchanged
  std::optional<ScenarioLayer> override_layer;  // merged over every run's scenario, last
  bool write_vtk = true;
  std::optional<std::string> device;
};

// Reads and checks a manifest; every problem is reported at once as an InputError (file, line, key, reason).
// Checks names (safe folder names, unique), seeds (unique, >= 0) and that every named file exists; the
// scenarios themselves are checked by each run, so one bad scenario fails its runs only.
BatchManifest load_batch_manifest(const std::filesystem::path& file);

// A name usable as one folder: 1-64 characters of [A-Za-z0-9_.-], not "." or "..".
bool is_safe_folder_name(std::string_view name);

}  // namespace heliostand
