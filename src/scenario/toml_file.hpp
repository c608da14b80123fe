#pragma once
// A TOML file a user hands in (a stand scenario, a batch manifest, a seed-000 experiment's scenario), read whole or
// refused as bad input: a missing, unreadable or folder path, or text that is not TOML, is an InputError naming the
// file (and the line, for TOML) with the reason. toml++ alone would call a missing file "File could not be opened for
// reading" and read a folder as an empty table, which a reader then reports as missing keys.
#include <filesystem>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace heliostand {

// `what` names the file's role in the message ("cannot read the scenario: No such file or directory"); `label` is
// how the message names the file (its path as the user gave it).
toml::table read_toml_file(const std::filesystem::path& file, const std::string& label, std::string_view what);

}  // namespace heliostand
