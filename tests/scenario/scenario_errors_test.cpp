// Every class of scenario error, each checked for file, line, key path and reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenario/scenario.hpp"
#include "scenario/scenario_test_files.hpp"
#include "survey/read_survey.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using testing::minimal_stand;
using testing::write_scenario;
using ::testing::ElementsAre;

using testing::stands;

using testing::scenario_problems;

TEST(ScenarioErrors, UnreadableFileAndSyntaxError) {
  EXPECT_THAT(input_problems([] { load_scenario("/nonexistent/heliostand/scenario.toml"); }),
              ElementsAre("/nonexistent/heliostand/scenario.toml: cannot read the scenario: No such file or directory"));
  const auto syntax = input_problems([] { load_scenario(stands / "bad" / "scenario_syntax_error.toml"); });
  ASSERT_EQ(syntax.size(), 1u);
  EXPECT_THAT(syntax[0], ::testing::StartsWith((stands / "bad" / "scenario_syntax_error.toml").string() +
                                               ":3: not valid TOML: "));
}

TEST(ScenarioErrors, MissingTablesAndRequiredKeys) {
  EXPECT_THAT(scenario_problems("missing_tables", "# nothing\n"),
              ElementsAre("scenario.toml: key 'stand': required table missing (it names the survey, the stand age and "
                          "the plot)",
                          "scenario.toml: key 'run': required table missing (it gives at least the years to simulate)"));
  EXPECT_THAT(scenario_problems("missing_keys", "[stand]\nsurvey = \"survey.csv\"\n[run]\nseed = 3\n"),
              ElementsAre("scenario.toml:1: key 'stand.age_at_survey': required key missing",
                          "scenario.toml:1: key 'stand.x_min': required key missing",
                          "scenario.toml:1: key 'stand.y_min': required key missing",
                          "scenario.toml:1: key 'stand.x_max': required key missing",
                          "scenario.toml:1: key 'stand.y_max': required key missing",
                          "scenario.toml:3: key 'run.years': required key missing"));
}

TEST(ScenarioErrors, UnknownKeysAndTables) {
  EXPECT_THAT(scenario_problems("unknown", minimal_stand + "yeras = 3\n[hollows]\ndepth_m = 2\n[light]\nsky_band = 8\n"),
              ElementsAre("scenario.toml:12: key 'hollows': unknown table or key (known: stand, run, species, light, "
                          "competition, thinning, roots, soil, coupling, root_pruning, hollow)",
                          "scenario.toml:11: key 'run.yeras': unknown key (known keys here: detail, device, "
                          "output_interval, roots_output_interval, seed, vtk_compression, years)",
                          "scenario.toml:15: key 'light.sky_band': unknown key (known keys here: cutoff_m, exact, "
                          "far_field_bias_correction, far_field_cell_m, far_field_hand_over_cells, far_field_table_mb, ground_albedo, "
                          "intensity_ratio, periodic, plot_x_max, plot_x_min, plot_y_max, plot_y_min, "
                          "sky, sky_bands, sky_scale, sky_sectors, transmittance)"));
}

TEST(ScenarioErrors, WrongTypes) {
  EXPECT_THAT(scenario_problems("types", minimal_stand +
                                       "seed = 1.5\n"
                                       "device = 1\n"
                                       "[light]\n"
                                       "exact = \"yes\"\n"
                                       "transmittance = \"half\"\n"
                                       "far_field_bias_correction = 1\n"
                                       "[species]\n"
                                       "todomatsu = 3\n"),
              ElementsAre("scenario.toml:11: key 'run.seed': expected an integer >= 0, got a floating-point number",
                          "scenario.toml:12: key 'run.device': expected a string, got an integer",
                          "scenario.toml:18: key 'species.todomatsu': expected a table of species parameters "
                          "([species.NAME]), got an integer",
                          "scenario.toml:15: key 'light.transmittance': expected a number in (0, 1], got a string",
                          "scenario.toml:14: key 'light.exact': expected true or false, got a string",
                          "scenario.toml:16: key 'light.far_field_bias_correction': expected true or false, got an "
                          "integer"));
}

TEST(ScenarioErrors, LevelOfDetailAndRootsOutputInterval) {
  EXPECT_THAT(scenario_problems("detail", minimal_stand + "detail = \"leaves\"\nroots_output_interval = -1\n"),
              ElementsAre("scenario.toml:11: key 'run.detail': expected \"full\", \"envelope\" or \"cone\", got \"leaves\"",
                          "scenario.toml:12: key 'run.roots_output_interval': expected an integer in [0, 5000], got -1"));
}

TEST(ScenarioErrors, VtkCompression) {
  EXPECT_THAT(scenario_problems("compression", minimal_stand + "vtk_compression = \"gzip\"\n"),
              ElementsAre("scenario.toml:11: key 'run.vtk_compression': expected \"lz4\", \"zlib\" or \"none\", got "
                          "\"gzip\""));
  EXPECT_THAT(scenario_problems("compression_type", minimal_stand + "vtk_compression = 6\n"),
              ElementsAre("scenario.toml:11: key 'run.vtk_compression': expected a string, got an integer"));
}

TEST(ScenarioErrors, SkyIsOneOfItsNames) {
  EXPECT_THAT(scenario_problems("sky", minimal_stand + "[light]\nsky = \"sunny\"\n"),
              ElementsAre("scenario.toml:12: key 'light.sky': expected \"overcast\" or \"kanamaru\", got \"sunny\""));
}

TEST(ScenarioErrors, NoSpeciesMayTakeTheWholeStandsName) {
  EXPECT_THAT(scenario_problems("species_all", minimal_stand + "[species.all]\nheight_k = 0.03\n"),
              ElementsAre("scenario.toml:11: key 'species.all': \"all\" is the whole stand's name in stand_table.csv; "
                          "give the species another name"));
}

TEST(ScenarioErrors, OutOfRangeValues) {
  std::string toml = minimal_stand;
  toml.replace(toml.find("years = 10"), 10, "years = -5");
  EXPECT_THAT(scenario_problems("range", toml +
                                       "output_interval = 0\n"
                                       "[species.todomatsu]\n"
                                       "height_m = 1.0\n"
                                       "initial_crown_angle_deg = 95\n"
                                       "max_order = 0\n"
                                       "[light]\n"
                                       "sky_bands = 15\n"
                                       "cutoff_m = 0\n"),
              ElementsAre("scenario.toml:10: key 'run.years': expected an integer in [1, 5000], got -5",
                          "scenario.toml:11: key 'run.output_interval': expected an integer in [1, 5000], got 0",
                          "scenario.toml:13: key 'species.todomatsu.height_m': expected a number in [0, 0.8], got 1 (eq. 1: "
                          "p = 1/(1 - m) <= 5; fitted height curves have p of about 1-3, and beyond it the calibrated "
                          "asymptote of a young tree runs to kilometres)",
                          "scenario.toml:14: key 'species.todomatsu.initial_crown_angle_deg': expected a number in "
                          "(0, 90), got 95",
                          "scenario.toml:15: key 'species.todomatsu.max_order': expected an integer in [1, 10], got 0",
                          "scenario.toml:18: key 'light.cutoff_m': expected a number in (0, 1000], got 0",
                          "scenario.toml:17: key 'light.sky_bands': must be even (the upper hemisphere is the first "
                          "half), got 15"));
}

TEST(ScenarioErrors, BadPlotBoundsAndSurveyPath) {
  EXPECT_THAT(scenario_problems("bounds", "[stand]\nsurvey = \"nothere.csv\"\nage_at_survey = 0\nx_min = 5\ny_min = 0\n"
                                    "x_max = 5\ny_max = -1\n[run]\nyears = 1\n"),
              // The path is shown as the scenario's folder (stripped here) joined with the key's value.
              ElementsAre("scenario.toml:2: key 'stand.survey': survey file \"nothere.csv\" not found (paths are "
                          "relative to the scenario file)",
                          "scenario.toml:3: key 'stand.age_at_survey': expected an integer in [1, 100], got 0",
                          "scenario.toml:6: key 'stand.x_max': must be greater than x_min (5), got 5",
                          "scenario.toml:7: key 'stand.y_max': must be greater than y_min (0), got -1"));
}

TEST(ScenarioErrors, SpeciesConsistencyAndDefaultSpecies) {
  std::string toml = minimal_stand;
  toml.insert(toml.find("[run]"), "default_species = \"ezomatsu\"\n");  // line 9
  EXPECT_THAT(scenario_problems("species", toml +
                                         "[species.todomatsu]\n"          // 12
                                         "whorl_b3 = -10\n"
                                         "leaf_ball_min_radius_m = 0.5\n"
                                         "leaf_ball_max_radius_m = 0.2\n"),
              ElementsAre("scenario.toml:12: key 'species.todomatsu.whorl_b3': first-order branches per whorl a3 x + "
                          "b3 = -2.248 (eq. 3) must be in [1, 20] (conifers carry 3-8 first-order branches per whorl; three "
                          "trees took 15 s at 20 per whorl and 263 s at 103)",
                          "scenario.toml:15: key 'species.todomatsu.leaf_ball_max_radius_m': must not be below "
                          "leaf_ball_min_radius_m (0.5), got 0.2",
                          "scenario.toml:9: key 'stand.default_species': \"ezomatsu\" is not a defined species "
                          "(defined: todomatsu)"));
}

TEST(ScenarioErrors, ThinningStructure) {
  EXPECT_THAT(scenario_problems("thinning_structure", minimal_stand +
                                                    "[[thinning]]\n"                                // 11
                                                    "method = \"random\"\n"
                                                    "[[thinning]]\n"                                // 13
                                                    "age = 25\nmethod = \"ids\"\ntarget_stems_per_ha = 100\n"
                                                    "[[thinning]]\n"                                // 17
                                                    "age = 25\nmethod = \"from_below\"\nids = [\"1\"]\n"
                                                    "[[thinning]]\n"                                // 21
                                                    "age = 25\nmethod = \"from_above\"\ntarget_stems_per_ha = 300\n"
                                                    "target_basal_area_m2_per_ha = 20\nnote = \"x\"\n"
                                                    "[[thinning]]\n"                                // 27
                                                    "age = 26\nmethod = \"ids\"\nids = [\"1\", 2.5]\n"),
              ElementsAre("scenario.toml:11: key 'thinning[1].age': required key missing (or, instead of a fixed age, "
                          "a condition: when_basal_area_exceeds_m2_per_ha or when_top_height_reaches_m)",
                          "scenario.toml:12: key 'thinning[1].method': expected \"ids\", \"from_below\", "
                          "\"from_above\", \"neutral\", \"crop_tree\", \"dbh_class\" or \"rows\", got \"random\"",
                          "scenario.toml:13: key 'thinning[2].ids': required key missing (method \"ids\" names the "
                          "trees to remove)",
                          "scenario.toml:16: key 'thinning[2].target_stems_per_ha': not used by method \"ids\" (remove "
                          "the key or change the method)",
                          "scenario.toml:20: key 'thinning[3].ids': not used by method \"from_below\" (it chooses "
                          "trees by size)",
                          "scenario.toml:17: key 'thinning[3]': method \"from_below\" needs exactly one of "
                          "target_stems_per_ha, target_basal_area_m2_per_ha, remove_fraction and "
                          "remove_basal_area_fraction, got none",
                          "scenario.toml:26: key 'thinning[4].note': unknown key (known keys here: age, "
                          "competitor_radius_m, competitors_per_crop_tree, crop_tree_spacing_m, crop_trees_per_ha, "
                          "dbh_max_cm, dbh_min_cm, first_row, ids, method, protect_habitat_trees, reason, "
                          "remove_basal_area_fraction, remove_fraction, repeat, repeat_every_years, row_azimuth_deg, "
                          "row_interval, row_tolerance_m, target_basal_area_m2_per_ha, target_stems_per_ha, "
                          "when_basal_area_exceeds_m2_per_ha, when_top_height_reaches_m)",
                          "scenario.toml:21: key 'thinning[4]': method \"from_above\" needs exactly one of "
                          "target_stems_per_ha, target_basal_area_m2_per_ha, remove_fraction and "
                          "remove_basal_area_fraction, got target_stems_per_ha and target_basal_area_m2_per_ha",
                          "scenario.toml:30: key 'thinning[5].ids[2]': expected a tree id (string or integer), got a "
                          "floating-point number"));
}

TEST(ScenarioErrors, ThinningAgainstTheRunAndTheSurvey) {
  // Four trees on 0.01 ha = 400 stems/ha. Survey at 20, run to 30.
  EXPECT_THAT(scenario_problems("thinning_checks", minimal_stand +
                                                 "[[thinning]]\nage = 19\nmethod = \"ids\"\nids = [\"1\"]\n"    // 11
                                                 "[[thinning]]\nage = 31\nmethod = \"ids\"\nids = [\"2\"]\n"    // 15
                                                 "[[thinning]]\nage = 22\nmethod = \"ids\"\nids = [\"9\", \"1\"]\n"  // 19
                                                 "[[thinning]]\nage = 24\nmethod = \"from_below\"\n"            // 23
                                                 "target_stems_per_ha = 300\n"                                   // 26
                                                 "[[thinning]]\nage = 26\nmethod = \"from_above\"\n"            // 27
                                                 "target_stems_per_ha = 300\n"),                                 // 30
              ElementsAre("scenario.toml:12: key 'thinning[1].age': thinning at age 19 is before the survey (stand "
                          "age 20)",
                          "scenario.toml:16: key 'thinning[2].age': thinning at age 31 is after the end of the run "
                          "(stand age 30)",
                          "scenario.toml:22: key 'thinning[3].ids': tree id \"9\" is not in the survey",
                          "scenario.toml:22: key 'thinning[3].ids': tree id \"1\" is already removed by thinning[1]",
                          "scenario.toml:26: key 'thinning[4].target_stems_per_ha': target 300 stems/ha is not below "
                          "the stand's density at that age (at most 300.0 stems/ha: 4 surveyed trees on 0.01 ha, less "
                          "earlier thinnings)",
                          "scenario.toml:30: key 'thinning[5].target_stems_per_ha': target 300 stems/ha is not below "
                          "the stand's density at that age (at most 300.0 stems/ha: 4 surveyed trees on 0.01 ha, less "
                          "earlier thinnings)"));
}

TEST(ScenarioErrors, AStemTargetMustFallBelowTheEarlierOne) {
  // 400 stems/ha at the survey; thinned to 300 at age 22, a later target of 350 cannot be a thinning.
  // A basal-area event in between does not change what is known about stems.
  EXPECT_THAT(scenario_problems("falling_targets", minimal_stand +
                                                 "[[thinning]]\nage = 25\nmethod = \"from_below\"\n"   // 11
                                                 "target_stems_per_ha = 350\n"                              // 14
                                                 "[[thinning]]\nage = 22\nmethod = \"from_below\"\n"   // 15
                                                 "target_stems_per_ha = 300\n"                              // 18
                                                 "[[thinning]]\nage = 23\nmethod = \"from_above\"\n"
                                                 "target_basal_area_m2_per_ha = 10\n"),
              ElementsAre("scenario.toml:14: key 'thinning[1].target_stems_per_ha': target 350 stems/ha is not below "
                          "the stand's density at that age (at most 300.0 stems/ha: 4 surveyed trees on 0.01 ha, less "
                          "earlier thinnings)"));
}

TEST(ScenarioErrors, SurveyProblemsAreListedWithTheScenarios) {
  // Unknown species in the survey, plus a scenario problem: both reported, each with its own file and kind.
  const std::string survey = "x,y,h,species\n1,1,9,todomatsu\n12,2,9,karamatsu\n";
  EXPECT_THAT(scenario_problems("survey_and_scenario", minimal_stand + "seed = -2\n", survey),
              ElementsAre("scenario.toml:11: key 'run.seed': expected an integer >= 0, got -2",
                          "survey.csv:3: column 'x': 12 is outside the plot (x from 0 to 10 m)",
                          "survey.csv:3: column 'species': unknown species \"karamatsu\" (the scenario defines: "
                          "todomatsu)"));
}

TEST(BadStands, EveryProblemOfTheBadKeysScenario) {
  const auto file = stands / "bad" / "scenario_bad_keys.toml";
  const std::string f = file.string();
  EXPECT_THAT(
      input_problems([&] { load_scenario(file); }),
      ElementsAre(f + ":9: key 'stand.colour': unknown key (known keys here: age_at_survey, default_species, multi_stem, "
                      "plot_margin_m, survey, survey_separator, survey_units, x_max, x_min, y_max, y_min)",
                  f + ":12: key 'run.years': expected an integer in [1, 5000], got a string",
                  f + ":13: key 'run.seed': expected an integer >= 0, got -1",
                  f + ":14: key 'run.output_interval': expected an integer in [1, 5000], got 0",
                  f + ":15: key 'run.device': expected \"auto\", \"reference\", \"opencl\" or \"opencl:N\", got \"gpu\"",
                  f + ":18: key 'species.todomatsu.height_k': expected a number in (0, 1], got -0.1",
                  f + ":19: key 'species.todomatsu.max_order': expected an integer in [1, 10], got a floating-point "
                      "number",
                  f + ":22: key 'light.transmittance': expected a number in (0, 1], got 1.5",
                  f + ":25: key 'thinning[1].age': thinning at age 18 is before the survey (stand age 20)",
                  f + ":27: key 'thinning[1].ids': tree id \"99\" is not in the survey",
                  f + ":32: key 'thinning[2].target_stems_per_ha': target 900 stems/ha is not below the stand's "
                      "density at that age (at most 700.0 stems/ha: 8 surveyed trees on 0.01 ha, less earlier "
                      "thinnings)"));
}

TEST(BadStands, EveryProblemOfTheBadSurvey) {
  const auto file = stands / "bad" / "scenario_bad_survey.toml";
  const std::string f = (stands / "bad" / "survey_many_problems.csv").string();
  EXPECT_THAT(input_problems([&] { load_scenario(file); }),
              ElementsAre(f + ":3: column 'height': expected a number, got \"12abc\"",
                          f + ":4: column 'height': expected a number > 0, got \"-3\"",
                          f + ":5: column 'id': duplicate id \"1\" (first used on line 2)",
                          f + ":6: column 'x': 12 is outside the plot (x from 0 to 10 m)",
                          f + ":7: column 'x,y': stands within 1 cm of the tree on line 2 (two trees at one position; set "
                          "stand.multi_stem if these are the stems of one tree)",
                          f + ":8: expected 7 fields (as in the header), got 5",
                          f + ":9: column 'dbh': expected a finite number, got \"nan\"",
                          f + ":9: column 'crown_base': crown base 9 m is not below the tree height 8.4 m"));
}

TEST(BadStands, SurveyWithoutPositionOrSizeColumns) {
  const auto file = (stands / "bad" / "survey_missing_columns.csv").string();
  EXPECT_THAT(input_problems([&] { read_survey(file); }),
              ElementsAre(file + ":1: column 'y': required column missing (accepted names: y, pos_y, position_y, y_coord, gy, each optionally with a unit: y_m)",
                          file + ":1: column 'height': neither a height nor a dbh column; one of them is required "
                                 "(accepted names: height, h, ht, tree_height, each optionally with a unit: height_m; dbh, d, d13, "
                                 "diameter, diam, bhd, each optionally with a unit: dbh_cm)"));
}

}  // namespace
}  // namespace heliostand
