#include "scenario/output_detail.hpp"

namespace heliostand {

std::string_view name_of(OutputDetail detail) {
  switch (detail) {
    case OutputDetail::full: return "full";
    case OutputDetail::envelope: return "envelope";
    case OutputDetail::cone: return "cone";
  }
  return "full";
}

std::optional<OutputDetail> parse_output_detail(std::string_view text) {
  for (OutputDetail detail : {OutputDetail::full, OutputDetail::envelope, OutputDetail::cone})
    if (text == name_of(detail)) return detail;
  return std::nullopt;
}

}  // namespace heliostand
