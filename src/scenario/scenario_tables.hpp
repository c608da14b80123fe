#pragma once
// One parse function per top-level scenario table. Each gets the table's node (null when the file has
// none, so it can report missing required keys), fills its part of the draft and reports problems.
// A new table (roots, hollows, ...) is a new function here and one line in scenario_table_parsers().
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "architecture/species.hpp"
#include "light/light_parameters.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_problems.hpp"
#include "scenario/toml_table_reader.hpp"
#include "survey/check_hollows.hpp"

namespace heliostand::scenario_detail {

// A scenario being assembled: what has been read so far, and what was valid enough to check others against.
struct ScenarioDraft {
  Scenario scenario;
  std::filesystem::path base_dir;           // the scenario file's folder: relative paths start here
  std::optional<std::string> survey_label;  // survey path as shown in messages (base_dir / value)
  int survey_key_line = 0;
  bool age_valid = false;
  bool plot_valid = false;
  bool years_valid = false;
  std::optional<std::string> default_species_key;  // stand.default_species as written
  int default_species_line = 0;
  std::vector<std::pair<std::string, int>> species_order;  // names in file order, with their lines
  // Per thinning event (same order as scenario.thinning, file order): where its keys were written.
  struct ThinningKeys {
    std::string path;  // "thinning[2]"
    int ids_line = 0;
    int target_line = 0;
    int method_line = 0;
    int first_row_line = 0;
    int crop_trees_line = 0;
  };
  std::vector<ThinningKeys> thinning_keys;
  // [[hollow]] entries, attached to their survey records once the survey is read.
  struct ScenarioHollow {
    std::string tree_id;
    int tree_line = 0;
    TreeHollow hollow;
  };
  std::vector<ScenarioHollow> hollows;
};

using TableParser = void (*)(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);

struct TableParserEntry {
  std::string_view key;
  TableParser parse;
};

void parse_stand(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_run(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_species(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_light(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_competition(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_thinning(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
// The "when" of one [[thinning]] (parse_thinning_when.cpp): age, or a condition, and its repetition.
void read_thinning_when(TomlTableReader& reader, const ScenarioDraft& draft, ThinningTrigger& when);
// Roots, soil, crown–root coupling and root pruning (parse_roots.cpp, parse_soil.cpp, parse_coupling.cpp,
// parse_root_pruning.cpp): all fill Scenario::roots.
void parse_roots(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_soil(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_coupling(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_root_pruning(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);
void parse_hollow(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems);

// After the survey is read: each [[hollow]] joins its tree's record (unknown ids are problems) and is
// checked against that tree's trunk (survey/check_hollows.hpp).
void attach_hollows_to_survey(ScenarioDraft& draft, ScenarioProblems& problems);

// After the survey is read: thinning ids exist and are removed once; stem targets fall over time. Then
// sorts the events by age.
void check_thinning_against_survey(ScenarioDraft& draft, ScenarioProblems& problems);

// After the survey is read: what the model can grow (check_model_limits.cpp). Every surveyed tree's age within
// limit::grown_tree_age; eq. 9's branch triangle open by limit::min_branch_triangle_opening_deg at the oldest age each
// species reaches (also after --years: Scenario::set_years).
struct CrownClosure {
  std::string species;
  double age_years, crown_angle_deg, opening_deg;
  std::string reason(const Scenario& scenario) const;
};
std::vector<CrownClosure> crown_closures(const Scenario& scenario);
void check_crown_closure(const ScenarioDraft& draft, ScenarioProblems& problems);
void check_tree_ages(const ScenarioDraft& draft, ScenarioProblems& problems);

// In the order they run: later tables may use what earlier ones resolved (light uses the stand's plot).
std::span<const TableParserEntry> scenario_table_parsers();

// The table at `node`, or null after reporting that `key` should be a table.
const toml::table* as_table(const toml::node* node, std::string_view key, ScenarioProblems& problems);

// An array of tables ([[key]]): `parse` for each table with its path "key[i]" (1-based); anything else reported.
void for_each_table_of_array(const toml::node* node, std::string_view key, ScenarioProblems& problems,
                             const std::function<void(const toml::table&, const std::string& path)>& parse);

}  // namespace heliostand::scenario_detail
