#include "survey/read_survey.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "core/input_error.hpp"
#include "core/trim_blanks.hpp"
#include "survey/check_hollows.hpp"
#include "survey/csv_table.hpp"
#include "survey/hollow_cell.hpp"
#include "survey/multi_stem.hpp"
#include "survey/plausible_limits.hpp"
#include "survey/strict_number.hpp"
#include "survey/survey_columns.hpp"

namespace heliostand {

namespace {

constexpr std::size_t column_count = survey_column_count;

std::string read_whole_file(const std::filesystem::path& file, const std::string& label) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw InputError({{label, 0, "", "cannot read the survey: it is a directory"}});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError({{label, 0, "", fmt::format("cannot read the survey: {}", std::strerror(errno))}});
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Where each survey column sits in the file, and the name the file gives it (used in messages, so the
// user sees the header they wrote; the canonical name for a column the file lacks).
struct ColumnLayout {
  std::array<int, column_count> index{};
  std::array<std::string, column_count> header_name{};
  std::array<double, column_count> unit_factor{};  // file unit -> canonical unit
  std::size_t field_count = 0;
  bool decimal_comma = false;  // ';'- or tab-separated: "12,5" is 12.5

  ColumnLayout() {
    index.fill(-1);
    unit_factor.fill(1.0);
    for (const auto& info : survey_columns()) header_name[slot(info.column)] = std::string(info.name);
  }
  static std::size_t slot(SurveyColumn c) { return static_cast<std::size_t>(c); }
  bool has(SurveyColumn c) const { return index[slot(c)] >= 0; }
  const std::string& name(SurveyColumn c) const { return header_name[slot(c)]; }
};

std::string accepted_names(SurveyColumn column) {
  const SurveyColumnInfo& info = survey_column_info(column);
  const std::string names = fmt::format("{}", fmt::join(info.aliases.begin(), info.aliases.end(), ", "));
  if (info.quantity == Quantity::none) return names;
  return fmt::format("{}, each optionally with a unit: {}_{}", names, info.name, canonical_unit(info.quantity));
}

// The factor from the column's unit — its header's suffix, or the scenario's survey_units — to the canonical
// unit; a unit that does not fit the column, or a header and a scenario that disagree, is a problem.
double column_unit_factor(const std::string& written, const NamedColumn& named, const SurveyFormat& format,
                          const std::string& file, int line, std::vector<InputProblem>& problems) {
  const SurveyColumnInfo& info = survey_column_info(named.column);
  const auto scenario = format.units.find(named.column);
  std::string unit = named.unit;
  if (scenario != format.units.end()) {
    if (!unit.empty() && unit != scenario->second) {
      problems.push_back({file, line, written,
                          fmt::format("the header says the unit is '{}' but the scenario's survey_units says '{}'",
                                      unit, scenario->second)});
      return 1.0;
    }
    unit = scenario->second;
  }
  if (unit.empty()) return 1.0;
  if (const auto factor = unit_factor(info.quantity, unit)) return *factor;
  problems.push_back({file, line, written,
                      info.quantity == Quantity::none
                          ? fmt::format("column '{}' has no unit, got '{}'", info.name, unit)
                          : fmt::format("'{}' is not a unit of {} (accepted: {})", unit, info.name,
                                        accepted_units(info.quantity))});
  return 1.0;
}

ColumnLayout read_header(const CsvRecord& header, char separator, const std::string& file, const SurveyFormat& format,
                         std::vector<InputProblem>& problems, std::vector<std::string>& warnings) {
  ColumnLayout layout;
  layout.field_count = header.fields.size();
  layout.decimal_comma = separator != ',';
  for (std::size_t i = 0; i < header.fields.size(); ++i) {
    const std::string written(trim_blanks(header.fields[i]));
    const auto named = survey_column_named(written);
    if (!named) {
      warnings.push_back(fmt::format("{}: column '{}' is not a survey column; ignored", file, written));
      continue;
    }
    const auto slot = static_cast<std::size_t>(named->column);
    if (layout.index[slot] >= 0) {
      problems.push_back({file, header.line, written,
                          fmt::format("names the same column as '{}' (column {})", layout.header_name[slot],
                                      layout.index[slot] + 1)});
      continue;
    }
    layout.index[slot] = static_cast<int>(i);
    layout.header_name[slot] = written;
    layout.unit_factor[slot] = column_unit_factor(written, *named, format, file, header.line, problems);
  }
  for (SurveyColumn required : {SurveyColumn::x, SurveyColumn::y}) {
    if (!layout.has(required)) {
      problems.push_back({file, header.line, std::string(survey_column_info(required).name),
                          fmt::format("required column missing (accepted names: {})", accepted_names(required))});
    }
  }
  if (!layout.has(SurveyColumn::height) && !layout.has(SurveyColumn::dbh)) {
    problems.push_back({file, header.line, "height",
                        fmt::format("neither a height nor a dbh column; one of them is required (accepted names: "
                                    "{}; {})",
                                    accepted_names(SurveyColumn::height), accepted_names(SurveyColumn::dbh))});
  }
  if (layout.has(SurveyColumn::crown_base) && layout.has(SurveyColumn::crown_ratio)) {
    problems.push_back({file, header.line, layout.name(SurveyColumn::crown_ratio),
                        fmt::format("give either a crown base ('{}') or a crown ratio column, not both",
                                    layout.name(SurveyColumn::crown_base))});
  }
  if (layout.has(SurveyColumn::crown_radius) && layout.has(SurveyColumn::crown_diameter)) {
    problems.push_back({file, header.line, layout.name(SurveyColumn::crown_diameter),
                        fmt::format("give either a crown radius ('{}') or a crown diameter column, not both",
                                    layout.name(SurveyColumn::crown_radius))});
  }
  return layout;
}

// What a row says, before imputation: a number per numeric column when the cell is not empty.
struct RowValues {
  std::array<std::optional<double>, column_count> number;
  std::array<bool, column_count> bad{};  // the cell held something that is not an acceptable value
  std::string id, species, hollow, life_stage;
  bool ok = true;
};

enum class Sign { any, positive, non_negative };

class RowReader {
 public:
  RowReader(const ColumnLayout& layout, const std::string& file, std::vector<InputProblem>& problems)
      : layout_(layout), file_(file), problems_(problems) {}

  RowValues read(const CsvRecord& record) {
    RowValues row;
    record_ = &record;
    row_ = &row;
    if (layout_.has(SurveyColumn::id)) row.id = cell(SurveyColumn::id);
    if (layout_.has(SurveyColumn::species)) row.species = cell(SurveyColumn::species);
    if (layout_.has(SurveyColumn::hollow)) row.hollow = cell(SurveyColumn::hollow);
    if (layout_.has(SurveyColumn::life_stage)) row.life_stage = normalise_header_name(cell(SurveyColumn::life_stage));
    number(SurveyColumn::x, Sign::any, true);
    number(SurveyColumn::y, Sign::any, true);
    number(SurveyColumn::height, Sign::positive, false);
    number(SurveyColumn::dbh, Sign::positive, false);
    number(SurveyColumn::crown_radius, Sign::positive, false);
    number(SurveyColumn::crown_diameter, Sign::positive, false);
    number(SurveyColumn::crown_base, Sign::non_negative, false);
    number(SurveyColumn::age, Sign::positive, false);
    number(SurveyColumn::crown_ratio, Sign::positive, false);
    return row;
  }

  void problem(SurveyColumn column, std::string reason) {
    problems_.push_back({file_, record_->line, layout_.name(column), std::move(reason)});
    row_->bad[static_cast<std::size_t>(column)] = true;
    row_->ok = false;
  }

 private:
  std::string cell(SurveyColumn column) const {
    return std::string(trim_blanks(record_->fields[static_cast<std::size_t>(layout_.index[static_cast<std::size_t>(column)])]));
  }

  void number(SurveyColumn column, Sign sign, bool required) {
    if (!layout_.has(column)) return;
    const std::string text = cell(column);
    if (text.empty()) {
      if (required) problem(column, "a value is required here (the cell is empty)");
      return;
    }
    const auto value = parse_strict_number(layout_.decimal_comma ? with_decimal_point(text) : text);
    if (!value) return problem(column, fmt::format("expected a number, got \"{}\"", text));
    if (!std::isfinite(*value)) return problem(column, fmt::format("expected a finite number, got \"{}\"", text));
    if (sign == Sign::positive && *value <= 0)
      return problem(column, fmt::format("expected a number > 0, got \"{}\"", text));
    if (sign == Sign::non_negative && *value < 0)
      return problem(column, fmt::format("expected a number >= 0, got \"{}\"", text));
    const double converted = *value * layout_.unit_factor[static_cast<std::size_t>(column)];
    if (const auto limit = plausible_limit(column); limit && std::abs(converted) > limit->max) {
      const Quantity quantity = survey_column_info(column).quantity;
      return problem(column, fmt::format("{:g} {} is beyond the plausible limit of {:g} {} ({})", converted,
                                         canonical_unit(quantity), limit->max, canonical_unit(quantity), limit->why));
    }
    row_->number[static_cast<std::size_t>(column)] = converted;
  }

  // "12,5" -> "12.5": in a semicolon- or tab-separated file the comma is the decimal mark (European
  // spreadsheets). Only a single comma in a cell without a point is read so; "1,234.5" stays an error.
  static std::string with_decimal_point(std::string text) {
    if (std::count(text.begin(), text.end(), ',') == 1 && text.find('.') == std::string::npos)
      text[text.find(',')] = '.';
    return text;
  }

  const ColumnLayout& layout_;
  const std::string& file_;
  std::vector<InputProblem>& problems_;
  const CsvRecord* record_ = nullptr;
  RowValues* row_ = nullptr;
};

// Counts imputed values per column, to give one warning per column rather than one per tree.
struct ImputationTally {
  std::array<int, column_count> missing{};
  void count(SurveyColumn column) { ++missing[static_cast<std::size_t>(column)]; }
};

class SurveyBuilder {
 public:
  SurveyBuilder(const ColumnLayout& layout, const SurveyReadOptions& options, const std::string& file,
                std::vector<InputProblem>& problems)
      : layout_(layout), options_(options), file_(file), problems_(problems) {}

  void add(const CsvRecord& record) {
    if (record.fields.size() != layout_.field_count) {
      problems_.push_back({file_, record.line, "",
                           fmt::format("expected {} fields (as in the header), got {}", layout_.field_count,
                                       record.fields.size())});
      return;
    }
    RowReader reader(layout_, file_, problems_);
    RowValues row = reader.read(record);
    if (skipped_for_life_stage(row, reader)) return;
    SurveyRecord tree;
    tree.line = record.line;
    complete(row, reader, tree);
    if (!row.ok) return;
    note_slenderness(tree);
    trees_.push_back(std::move(tree));
  }

  std::vector<SurveyRecord> take_trees() { return std::move(trees_); }
  std::size_t skipped() const { return seedlings_ + dead_; }

  std::vector<std::string> warnings(std::size_t records) const {
    std::vector<std::string> out;
    auto warn = [&](SurveyColumn column, const std::string& rule) {
      const int n = tally_.missing[static_cast<std::size_t>(column)];
      if (n == 0) return;
      // Id, age and species without a column are not guesses but the stand's own facts (line numbers,
      // the scenario's stand age and default species): warn only about empty cells in a column that exists.
      const bool stand_default = column == SurveyColumn::id || column == SurveyColumn::age ||
                                 column == SurveyColumn::species;
      if (stand_default && !layout_.has(column)) return;
      out.push_back(fmt::format("{}: column '{}': {} of {} values missing; {}", file_, layout_.name(column), n,
                                records, rule));
    };
    warn(SurveyColumn::id, "using the line number as id");
    warn(SurveyColumn::height, "imputed from DBH by seed 001 eq. 2 (below-crown coefficients), inverted");
    warn(SurveyColumn::dbh, "imputed from height by seed 001 eq. 2 (below-crown coefficients)");
    const std::string crown_rule = fmt::format("crown radius imputed as {:g} m + {:g} m/cm x DBH",
                                               options_.allometry.crown_radius_intercept_m,
                                               options_.allometry.crown_radius_per_dbh_m_per_cm);
    warn(SurveyColumn::crown_radius, crown_rule);
    warn(SurveyColumn::crown_diameter, crown_rule);
    warn(SurveyColumn::crown_base,
         fmt::format("imputed as {:g} x height", options_.allometry.crown_base_height_ratio));
    warn(SurveyColumn::age, options_.stand_age_years
                                ? fmt::format("using the stand age at the survey, {:g} years", *options_.stand_age_years)
                                : std::string("no stand age to use"));
    warn(SurveyColumn::species, fmt::format("using the default species '{}'", options_.default_species));
    if (seedlings_ + dead_ > 0)
      out.push_back(fmt::format("{}: column '{}': {} seedlings and {} snags or other dead stems skipped (seedlings' "
                                "diameter is taken at 10 cm, not at breast height; dead stems are not grown)",
                                file_, layout_.name(SurveyColumn::life_stage), seedlings_, dead_));
    if (!slender_lines_.empty())
      out.push_back(fmt::format("{}: {} trees taller than {:g} m have a height/DBH ratio outside [{:g}, {:g}] (lines "
                                "{}{}): check the units of height and dbh",
                                file_, slender_lines_.size(), slenderness_min_height_m, slenderness_min,
                                slenderness_max,
                                fmt::join(slender_lines_.begin(),
                                          slender_lines_.begin() + std::min<std::size_t>(slender_lines_.size(), 5),
                                          ", "),
                                slender_lines_.size() > 5 ? ", ..." : ""));
    return out;
  }

 private:
  using C = SurveyColumn;
  std::optional<double> value(const RowValues& row, C c) const { return row.number[static_cast<std::size_t>(c)]; }

  const SpeciesParameters& species_of(const std::string& name) const {
    static const SpeciesParameters todomatsu{};
    auto it = options_.species.find(name);
    return it == options_.species.end() ? todomatsu : it->second;
  }

  // SORTIE-ND tree maps list seedlings (diameter at 10 cm, not DBH) and snags with the living trees: neither is
  // a tree heliostand can start as surveyed, so they are counted and left out.
  bool skipped_for_life_stage(const RowValues& row, RowReader& reader) {
    const std::string& stage = row.life_stage;
    if (stage.empty() || stage == "sapling" || stage == "adult") return false;
    if (stage == "seedling") return ++seedlings_, true;
    if (stage == "snag" || stage == "stump" || stage == "woody_debris") return ++dead_, true;
    reader.problem(C::life_stage, fmt::format("unknown life stage \"{}\" (known: seedling, sapling, adult, snag, "
                                              "stump, woody_debris)",
                                              stage));
    return true;
  }

  void note_slenderness(const SurveyRecord& tree) {
    if (tree.height_m <= slenderness_min_height_m || tree.dbh_cm <= 0) return;
    const double slenderness = tree.height_m / (tree.dbh_cm / 100.0);
    if (slenderness < slenderness_min || slenderness > slenderness_max) slender_lines_.push_back(tree.line);
  }

  // Fills the record from the row, imputing what is missing; every gap that cannot be filled is a problem.
  void complete(RowValues& row, RowReader& reader, SurveyRecord& tree) {
    tree.x_m = value(row, C::x).value_or(0);
    tree.y_m = value(row, C::y).value_or(0);
    if (row.number[static_cast<std::size_t>(C::x)] && row.number[static_cast<std::size_t>(C::y)] && options_.plot &&
        !options_.plot->contains(tree.x_m, tree.y_m)) {
      const auto& p = *options_.plot;
      if (tree.x_m < p.x_min || tree.x_m > p.x_max)
        reader.problem(C::x, fmt::format("{:g} is outside the plot (x from {:g} to {:g} m)", tree.x_m, p.x_min, p.x_max));
      if (tree.y_m < p.y_min || tree.y_m > p.y_max)
        reader.problem(C::y, fmt::format("{:g} is outside the plot (y from {:g} to {:g} m)", tree.y_m, p.y_min, p.y_max));
    }

    tree.id = row.id;
    if (tree.id.empty()) {
      tree.id = std::to_string(tree.line);
      tree.imputed.id = true;
      tally_.count(C::id);
    }
    tree.species = row.species;
    if (tree.species.empty()) {
      tree.species = options_.default_species;
      tree.imputed.species = true;
      tally_.count(C::species);
    } else if (!options_.species.empty() && !options_.species.count(tree.species)) {
      std::vector<std::string> known;
      for (const auto& [name, _] : options_.species) known.push_back(name);
      reader.problem(C::species, fmt::format("unknown species \"{}\" (the scenario defines: {})", tree.species,
                                             fmt::join(known, ", ")));
    }
    const SpeciesParameters& species = species_of(tree.species);

    complete_height_and_dbh(row, reader, species, tree);
    complete_crown(row, reader, tree);

    if (auto age = value(row, C::age)) {
      tree.age_years = *age;
    } else if (options_.stand_age_years) {
      tree.age_years = *options_.stand_age_years;
      tree.imputed.age = true;
      tally_.count(C::age);
    } else {
      reader.problem(C::age, "no age given, and no stand age to impute it from");
    }
    complete_hollows(row, reader, species, tree);
  }

  // The hollows in the cell, checked against the tree's trunk once its height and crown base are known.
  void complete_hollows(const RowValues& row, RowReader& reader, const SpeciesParameters& species,
                        SurveyRecord& tree) {
    if (row.hollow.empty()) return;
    auto parsed = parse_hollow_cell(row.hollow);
    if (auto* reason = std::get_if<std::string>(&parsed)) return reader.problem(C::hollow, *reason);
    for (const auto& spec : std::get<std::vector<hollow::HollowSpec>>(parsed))
      tree.hollows.push_back({spec, false, file_, tree.line, layout_.name(C::hollow), "column"});
    if (!row.ok) return;  // a bad height or crown base: no trunk to check against
    for (const InputProblem& problem : check_tree_hollows(tree, species)) reader.problem(C::hollow, problem.reason);
  }

  void complete_height_and_dbh(RowValues& row, RowReader& reader, const SpeciesParameters& species,
                               SurveyRecord& tree) {
    const auto height = value(row, C::height);
    const auto dbh = value(row, C::dbh);
    if (height) tree.height_m = *height;  // lets the crown base be checked even when the DBH is bad
    // A bad height or dbh cell is already reported; imputing from the other would only add noise.
    if (row.bad[static_cast<std::size_t>(C::height)] || row.bad[static_cast<std::size_t>(C::dbh)]) return;
    if (!height && !dbh) {
      reader.problem(layout_.has(C::height) ? C::height : C::dbh,
                     "neither height nor dbh given for this tree (one of them is required)");
      return;
    }
    if (height) {
      tree.height_m = *height;
    } else {
      tree.height_m = height_from_dbh_m(*dbh, species);
      tree.imputed.height = true;
      tally_.count(C::height);
    }
    if (dbh) {
      tree.dbh_cm = *dbh;
    } else if (tree.height_m <= breast_height_m) {
      reader.problem(layout_.has(C::dbh) ? C::dbh : C::height,
                     fmt::format("no dbh given, and a tree {:g} m tall is not above breast height ({:g} m) to "
                                 "impute one",
                                 tree.height_m, breast_height_m));
    } else {
      tree.dbh_cm = dbh_from_height_cm(tree.height_m, species);
      tree.imputed.dbh = true;
      tally_.count(C::dbh);
    }
  }

  void complete_crown(RowValues& row, RowReader& reader, SurveyRecord& tree) {
    if (auto radius = value(row, C::crown_radius)) {
      tree.crown_radius_m = *radius;
    } else if (auto diameter = value(row, C::crown_diameter)) {
      tree.crown_radius_m = *diameter / 2;
    } else {
      tree.crown_radius_m = crown_radius_from_dbh_m(tree.dbh_cm, options_.allometry);
      tree.imputed.crown_radius = true;
      tally_.count(layout_.has(C::crown_diameter) ? C::crown_diameter : C::crown_radius);
    }
    if (auto base = value(row, C::crown_base)) {
      tree.crown_base_m = *base;
      if (tree.height_m > 0 && *base >= tree.height_m) {
        reader.problem(C::crown_base, fmt::format("crown base {:g} m is not below the tree height {:g} m", *base,
                                                  tree.height_m));
      }
    } else if (auto ratio = value(row, C::crown_ratio)) {
      tree.crown_base_m = tree.height_m * (1.0 - *ratio);  // the live crown is `ratio` of the height
    } else {
      tree.crown_base_m = crown_base_from_height_m(tree.height_m, options_.allometry);
      tree.imputed.crown_base = true;
      tally_.count(C::crown_base);
    }
  }

  const ColumnLayout& layout_;
  const SurveyReadOptions& options_;
  const std::string& file_;
  std::vector<InputProblem>& problems_;
  std::vector<SurveyRecord> trees_;
  ImputationTally tally_;
  std::size_t seedlings_ = 0, dead_ = 0;
  std::vector<int> slender_lines_;
};

void check_unique_ids(const std::vector<SurveyRecord>& trees, const std::string& file, const std::string& column,
                      std::vector<InputProblem>& problems) {
  std::unordered_map<std::string, int> first_line;
  for (const auto& tree : trees) {
    auto [it, inserted] = first_line.emplace(tree.id, tree.line);
    if (!inserted) {
      problems.push_back({file, tree.line, column,
                          fmt::format("duplicate id \"{}\" (first used on line {})", tree.id, it->second)});
    }
  }
}

// Two stems within 1 cm: by default a typing slip that would put two trees in one (refused, each pair named);
// the scenario may declare them the stems of multi-stemmed trees, kept apart or merged (survey/multi_stem.hpp).
void resolve_shared_positions(std::vector<SurveyRecord>& trees, MultiStemPolicy policy, const std::string& file,
                              std::vector<InputProblem>& problems, std::vector<std::string>& warnings) {
  const auto groups = stems_sharing_a_position(trees);
  if (groups.empty()) return;
  std::size_t stems = 0;
  for (const auto& group : groups) stems += group.size();
  if (policy == MultiStemPolicy::refuse) {
    std::vector<std::pair<int, int>> clashes;  // (later line, earlier line)
    for (const auto& group : groups)
      for (std::size_t k = 1; k < group.size(); ++k) clashes.emplace_back(trees[group[k]].line, trees[group[k - 1]].line);
    std::sort(clashes.begin(), clashes.end());
    for (auto [line, other] : clashes)
      problems.push_back({file, line, "x,y",
                          fmt::format("stands within 1 cm of the tree on line {} (two trees at one position; set "
                                      "stand.multi_stem if these are the stems of one tree)",
                                      other)});
    return;
  }
  if (policy == MultiStemPolicy::separate) {
    warnings.push_back(fmt::format("{}: {} stems stand at {} shared positions; kept as separate trees (multi_stem = "
                                   "\"separate\")",
                                   file, stems, groups.size()));
    return;
  }
  std::vector<char> merged_away(trees.size(), 0);
  for (const auto& group : groups) {
    std::vector<const SurveyRecord*> stems_of_tree;
    for (std::size_t i : group) stems_of_tree.push_back(&trees[i]);
    MergedStems merged = merge_stems(stems_of_tree);
    if (!merged.tree) {
      problems.push_back({file, trees[group.front()].line, "x,y", merged.problem});
      continue;
    }
    trees[group.front()] = std::move(*merged.tree);
    for (std::size_t k = 1; k < group.size(); ++k) merged_away[group[k]] = 1;
  }
  std::vector<SurveyRecord> kept;
  for (std::size_t i = 0; i < trees.size(); ++i)
    if (!merged_away[i]) kept.push_back(std::move(trees[i]));
  trees = std::move(kept);
  warnings.push_back(fmt::format("{}: {} stems at {} shared positions merged into {} trees by basal area "
                                 "(multi_stem = \"merge\")",
                                 file, stems, groups.size(), groups.size()));
}

// The survey's records, split at the separator the scenario names or the header line shows.
struct SurveyTable {
  CsvTable csv;
  char separator = ',';
};

SurveyTable read_table(const std::filesystem::path& file, const std::string& label, const SurveyFormat& format) {
  const std::string text = read_whole_file(file, label);
  const char separator = separator_char(format.separator, text);
  return {parse_csv(text, label, separator), separator};
}

}  // namespace

Survey read_survey(const std::filesystem::path& file, const SurveyReadOptions& options) {
  const std::string label = file.string();
  SurveyTable read = read_table(file, label, options.format);
  CsvTable& table = read.csv;
  std::vector<InputProblem> problems = std::move(table.problems);
  Survey survey;
  survey.file = file;

  if (table.records.empty()) {
    problems.push_back({label, 0, "", "the survey is empty (expected a header row and one row per tree)"});
    throw InputError(std::move(problems));
  }
  const ColumnLayout layout =
      read_header(table.records.front(), read.separator, label, options.format, problems, survey.warnings);
  if (!problems.empty()) throw InputError(std::move(problems));
  if (table.records.size() == 1) {
    problems.push_back({label, table.records.front().line, "", "no tree records after the header"});
    throw InputError(std::move(problems));
  }

  SurveyBuilder builder(layout, options, label, problems);
  for (std::size_t i = 1; i < table.records.size(); ++i) builder.add(table.records[i]);
  survey.trees = builder.take_trees();
  const std::string id_column = layout.name(SurveyColumn::id);
  resolve_shared_positions(survey.trees, options.format.multi_stem, label, problems, survey.warnings);
  check_unique_ids(survey.trees, label, id_column, problems);
  if (!problems.empty()) {
    std::stable_sort(problems.begin(), problems.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
    throw InputError(std::move(problems));
  }
  if (survey.trees.empty()) {
    problems.push_back({label, 0, "", fmt::format("no tree to grow: all {} records were skipped", builder.skipped())});
    throw InputError(std::move(problems));
  }
  auto warnings = builder.warnings(table.records.size() - 1);
  survey.warnings.insert(survey.warnings.end(), warnings.begin(), warnings.end());
  return survey;
}

std::optional<PlotBounds> survey_extent(const std::filesystem::path& file, const SurveyFormat& format) {
  try {
    const std::string label = file.string();
    const SurveyTable read = read_table(file, label, format);
    const CsvTable& table = read.csv;
    if (table.records.size() < 2) return std::nullopt;
    std::vector<InputProblem> problems;
    std::vector<std::string> warnings;
    const ColumnLayout layout = read_header(table.records.front(), read.separator, label, format, problems, warnings);
    if (!problems.empty()) return std::nullopt;
    std::optional<PlotBounds> extent;
    for (std::size_t i = 1; i < table.records.size(); ++i) {
      if (table.records[i].fields.size() != layout.field_count) continue;
      RowReader reader(layout, label, problems);
      const RowValues row = reader.read(table.records[i]);
      const auto x = row.number[static_cast<std::size_t>(SurveyColumn::x)];
      const auto y = row.number[static_cast<std::size_t>(SurveyColumn::y)];
      if (!x || !y) continue;
      if (!extent) extent = PlotBounds{*x, *y, *x, *y};
      extent = PlotBounds{std::min(extent->x_min, *x), std::min(extent->y_min, *y), std::max(extent->x_max, *x),
                          std::max(extent->y_max, *y)};
    }
    return extent;
  } catch (const InputError&) {
    return std::nullopt;  // read_survey() reports it
  }
}

}  // namespace heliostand
