#pragma once
// How much of each tree the yearly VTK multiblock draws (scenario key `run.detail`, docs/formats.md):
//   full      every shoot, leaf ball and stem surface (the model's own view; about 30 MB a year for 62 trees)
//   envelope  the stem surface and one closed crown envelope per tree, coloured by the tree's light
//   cone      one cone per tree from its height, crown base and crown radius (a landscape of many hectares)
// The trees block (one point per tree with its measures) is written at every level.
#include <string_view>

#include "core/named_choice.hpp"

namespace heliostand {

enum class OutputDetail { full, envelope, cone };

// The level a hectare of 2,500 trees can be written at for 60 years in under 2 GB (docs/formats.md).
inline constexpr OutputDetail default_output_detail = OutputDetail::envelope;

inline constexpr NamedChoices<OutputDetail, 3> output_detail_names{
    {{OutputDetail::full, "full"}, {OutputDetail::envelope, "envelope"}, {OutputDetail::cone, "cone"}}};

constexpr std::string_view name_of(OutputDetail detail) { return name_in(output_detail_names, detail); }

}  // namespace heliostand
