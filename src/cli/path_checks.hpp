#pragma once
// The check of the options that name a file or a folder to write. An empty name (`-o ''`, most often a script's unset
// variable) passed as "not given" before: `bench light -o ''` wrote no file and said nothing, `bench stand --tables
// ''` kept no tables, `report -o ''` wrote into the default folder, and `grow --out ''` failed only after the device
// was opened, with "cannot create output folder : Invalid argument". Now: exit 2 before anything runs.
#include <CLI/CLI.hpp>

#include <string>

namespace heliostand {

// `what` is "file" or "folder": "--out: a folder name is expected, got an empty one".
inline CLI::Validator path_check(const std::string& what) {
  return CLI::Validator(
      [what](std::string& value) -> std::string {
        return value.empty() ? "a " + what + " name is expected, got an empty one" : std::string{};
      },
      std::string{});
}

}  // namespace heliostand
