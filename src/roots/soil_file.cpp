#include "roots/soil_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "core/input_error.hpp"

namespace heliostand::roots {

namespace {

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) {
    const auto first = field.find_first_not_of(" \t\r");
    const auto last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? std::string() : field.substr(first, last - first + 1));
  }
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

bool is_skippable(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

template <class Number>
std::optional<Number> parse(const std::string& text) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || ptr != end || text.empty()) return std::nullopt;
  return value;
}

}  // namespace

void read_soil_csv(const std::filesystem::path& path, SoilGrid& soil) {
  std::ifstream in(path);
  if (!in) throw InputError({{path.string(), 0, "", "cannot open the soil file"}});
  read_soil_csv(in, path.string(), soil);
}

void read_soil_csv(std::istream& in, const std::string& file_name, SoilGrid& soil) {
  std::vector<InputProblem> problems;
  auto problem = [&](int line, std::string field, std::string reason) {
    problems.push_back({file_name, line, std::move(field), std::move(reason)});
  };

  std::string line;
  int line_number = 0;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++line_number;
    if (is_skippable(line)) continue;
    header = split_fields(line);
    break;
  }
  if (header.empty()) throw InputError({{file_name, 0, "", "no header line 'i,j,k,moisture,nutrient'"}});

  const int header_line = line_number;
  int column_i = -1, column_j = -1, column_k = -1;
  std::vector<std::pair<int, SoilField>> value_columns;
  for (int c = 0; c < static_cast<int>(header.size()); ++c) {
    const std::string& name = header[c];
    if (name == "i") column_i = c;
    else if (name == "j") column_j = c;
    else if (name == "k") column_k = c;
    else if (name == "moisture") value_columns.emplace_back(c, SoilField::moisture);
    else if (name == "nutrient") value_columns.emplace_back(c, SoilField::nutrient);
    else problem(header_line, name, "unknown column (expected i, j, k, moisture, nutrient)");
  }
  for (auto [column, name] : {std::pair{column_i, "i"}, std::pair{column_j, "j"}, std::pair{column_k, "k"}})
    if (column < 0) problem(header_line, name, "missing column");
  if (value_columns.empty()) problem(header_line, "moisture", "need a moisture or a nutrient column");
  if (!problems.empty()) throw InputError(problems);

  // Values go into a copy first, so that a bad file leaves the caller's grid untouched.
  SoilGrid staged = soil;
  const glm::ivec3 vertices = soil.vertex_counts();
  std::set<std::tuple<int, int, int>> seen;
  while (std::getline(in, line)) {
    ++line_number;
    if (is_skippable(line)) continue;
    const std::vector<std::string> fields = split_fields(line);
    if (fields.size() != header.size()) {
      problem(line_number, "", fmt::format("expected {} fields, got {}", header.size(), fields.size()));
      continue;
    }
    glm::ivec3 index{};
    bool index_ok = true;
    const std::array<std::pair<int, const char*>, 3> index_columns{{{column_i, "i"}, {column_j, "j"}, {column_k, "k"}}};
    for (int axis = 0; axis < 3; ++axis) {
      const auto [column, name] = index_columns[axis];
      const auto value = parse<int>(fields[column]);
      if (!value || *value < 0 || *value >= vertices[axis]) {
        problem(line_number, name,
                fmt::format("expected a vertex index 0..{}, got \"{}\"", vertices[axis] - 1, fields[column]));
        index_ok = false;
      } else {
        index[axis] = *value;
      }
    }
    if (index_ok && !seen.emplace(index.x, index.y, index.z).second) {
      problem(line_number, "i", fmt::format("vertex ({}, {}, {}) is listed twice", index.x, index.y, index.z));
      index_ok = false;
    }
    for (auto [column, field] : value_columns) {
      const auto value = parse<double>(fields[column]);
      if (!value || !std::isfinite(*value) || *value < 0.0) {
        problem(line_number, header[column], fmt::format("expected a number >= 0, got \"{}\"", fields[column]));
        continue;
      }
      if (index_ok) staged.at(field, index.x, index.y, index.z) = *value;
    }
  }
  if (!problems.empty()) throw InputError(problems);
  for (auto [column, field] : value_columns) staged.set_capacity_to_current(field);
  soil = std::move(staged);
}

}  // namespace heliostand::roots
