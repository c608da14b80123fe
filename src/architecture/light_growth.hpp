#pragma once
// How much of its open-grown growth a shoot, a leader or a stem makes in the light it gets (docs/model.md
// "Growth from light"). Seed 001 §4 names the step: elongation from relative illuminance. The response form is
// LIGNUM's fip (Perttunen et al. 1996): nothing below a share of full light, linear up to saturation.
#include "architecture/species.hpp"

namespace heliostand {

// clamp((relative_light - zero) / (saturation - zero), 0, 1); a step at `zero` when saturation <= zero.
double light_response(double relative_light, double zero, double saturation);

double elongation_response(const SpeciesParameters& species, double relative_light);
double height_response(const SpeciesParameters& species, double relative_light);
// The share of the reference basal-area increment a tree makes when its crown absorbs `absorbed_share` of the
// light its established crown absorbed standing alone: ((share - compensation) / (1 - compensation)) ^ exponent,
// 0 below the compensation share.
double diameter_response(const SpeciesParameters& species, double absorbed_share);

}  // namespace heliostand
