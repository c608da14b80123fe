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
// The share of the taper's basal-area increment a tree makes at a pipe-model light share
// (ConiferTree::pipe_model_share): 0 below diameter_light_compensation, linear to 1 at diameter_light_saturation.
double diameter_response(const SpeciesParameters& species, double pipe_model_share);

}  // namespace heliostand
