#pragma once
// One column of an output table, declared once with its unit and meaning (as iLand's OutputColumn): a table's
// writer builds its header from the list of its columns and writes one field per column in that order, and a
// test holds docs/formats.md to the same list, so the file, the code and the documentation cannot drift apart.
#include <span>
#include <string>
#include <vector>

namespace heliostand {

struct OutputColumn {
  std::string name;
  std::string unit;     // as docs/formats.md writes it: "m", "m²/ha", "1/ha", "years"; "–" for counts, codes, text
  std::string meaning;  // one line; docs/formats.md may say more
};

inline std::vector<std::string> column_names(std::span<const OutputColumn> columns) {
  std::vector<std::string> names;
  for (const OutputColumn& column : columns) names.push_back(column.name);
  return names;
}

}  // namespace heliostand
