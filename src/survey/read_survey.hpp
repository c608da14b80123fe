#pragma once
// Reading a survey CSV into checked, complete tree records (docs/formats.md, "Survey CSV").
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "architecture/species.hpp"
#include "geometry/plot_bounds.hpp"
#include "survey/survey.hpp"
#include "survey/survey_allometry.hpp"
#include "survey/survey_format.hpp"

namespace heliostand {

struct SurveyReadOptions {
  // Trees must stand inside the plot (edges included). Without bounds, positions are not range-checked.
  std::optional<PlotBounds> plot;
  // Age given to records without one (the scenario's stand age at the survey). Without it, records
  // lacking an age are errors.
  std::optional<double> stand_age_years;
  // Known species by name; a record naming another is an error. Empty: any name is accepted and the
  // Todomatsu defaults drive the imputation.
  std::map<std::string, SpeciesParameters> species;
  std::string default_species = "todomatsu";  // for records without a species
  SurveyAllometry allometry;
  SurveyFormat format;  // separator, units, multi-stemmed trees
};

// Reads, checks and completes a survey. Throws InputError listing every problem found (each as
// FILE:LINE: column 'NAME': reason), so a user fixes the file in one pass. Problems are labelled with
// `file` exactly as given (keep it relative for readable messages).
Survey read_survey(const std::filesystem::path& file, const SurveyReadOptions& options = {});

// The rectangle spanned by the survey's stem positions (for plot bounds taken from the data), or nothing when
// the file cannot be read or holds no valid position: read_survey() then reports why.
std::optional<PlotBounds> survey_extent(const std::filesystem::path& file, const SurveyFormat& format = {});

}  // namespace heliostand
