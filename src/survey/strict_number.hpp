#pragma once
// Numbers in input files are read strictly: the whole cell must be one number ("12abc" and "1,5" are
// errors, not 12 and 1). Spaces around it and a leading '+' are tolerated.
#include <optional>
#include <string_view>

namespace heliostand {

// The number, or nothing when the text is not exactly one number. "nan" and "inf" parse (the caller
// rejects non-finite values with its own message).
std::optional<double> parse_strict_number(std::string_view text);

}  // namespace heliostand
