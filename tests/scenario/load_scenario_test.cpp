#include "scenario/scenario.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenario/scenario_test_files.hpp"

namespace heliostand {
using compute::DeviceChoice;
namespace {

using testing::minimal_stand;
using testing::write_scenario;

using testing::stands;

TEST(LoadScenario, MinimalScenarioTakesTheDefaults) {
  const auto file = write_scenario("minimal", minimal_stand);
  const Scenario s = load_scenario(file);
  EXPECT_EQ(s.stand.survey_file, std::filesystem::absolute(file.parent_path() / "survey.csv").lexically_normal());
  EXPECT_TRUE(s.stand.survey_file.is_absolute());
  EXPECT_EQ(s.stand.age_at_survey_years, 20);
  EXPECT_DOUBLE_EQ(s.plot_area_ha(), 0.01);  // 10 m x 10 m
  EXPECT_EQ(s.final_age_years(), 30);
  EXPECT_EQ(s.run.years, 10);
  EXPECT_EQ(s.run.seed, 1u);
  EXPECT_EQ(s.run.output_interval_years, 1);
  EXPECT_EQ(s.run.device, DeviceChoice{});
  EXPECT_EQ(s.run.output_detail, OutputDetail::envelope);
  EXPECT_EQ(s.run.vtk_compression, VtkCompression::lz4);
  // No [species]: one Todomatsu with the seed-001 values.
  ASSERT_EQ(s.species.size(), 1u);
  EXPECT_EQ(s.stand.default_species, "todomatsu");
  EXPECT_DOUBLE_EQ(s.species.at("todomatsu").site_asymptote_m, 28.0);
  EXPECT_DOUBLE_EQ(s.species.at("todomatsu").stem_a_below_crown, 3.336);
  // No [light]: the defaults, with the periodic domain on the plot.
  EXPECT_EQ(s.light.sky_bands, 16);
  EXPECT_DOUBLE_EQ(s.light.transmittance, 0.5);
  EXPECT_FALSE(s.light.periodic);
  EXPECT_TRUE(s.light.far_field_bias_correction);  // the light the growth is set on
  EXPECT_DOUBLE_EQ(s.light.plot_x_max, 10);
  EXPECT_DOUBLE_EQ(s.light.plot_y_max, 10);
  EXPECT_TRUE(s.thinning.empty());
  ASSERT_EQ(s.survey.trees.size(), 4u);
  EXPECT_EQ(s.species_of(s.survey.trees[0]).name, "todomatsu");
}

TEST(LoadScenario, VtkCompressionIsReadFromRun) {
  for (const auto& [text, compression] :
       {std::pair{"lz4", VtkCompression::lz4}, {"zlib", VtkCompression::zlib}, {"none", VtkCompression::none}}) {
    const Scenario s = load_scenario(
        write_scenario(std::string("compression-") + text,
                       minimal_stand + "vtk_compression = \"" + text + "\"\n"));  // minimal_stand ends in [run]
    EXPECT_EQ(s.run.vtk_compression, compression) << text;
  }
}

TEST(LoadScenario, SkyIsReadFromLight) {
  EXPECT_EQ(load_scenario(write_scenario("sky-default", minimal_stand)).light.sky,
            LightParameters::Sky::standard_overcast);
  for (const auto& [text, sky] : {std::pair{"overcast", LightParameters::Sky::standard_overcast},
                                  {"kanamaru", LightParameters::Sky::kanamaru}}) {
    const Scenario s = load_scenario(
        write_scenario(std::string("sky-") + text, minimal_stand + "[light]\nsky = \"" + text + "\"\n"));
    EXPECT_EQ(s.light.sky, sky) << text;
  }
}

// The periodic light domain: the plot unless [light] gives its own, and what the stand solver is handed
// (Scenario::stand_light) is that domain: a [light] domain used to be replaced by the plot without a word.
TEST(LoadScenario, StandLightWrapsTheLightDomain) {
  const Scenario plain = load_scenario(write_scenario("light-domain-plot", minimal_stand + "[light]\nperiodic = true\n"));
  EXPECT_DOUBLE_EQ(plain.stand_light().plot_x_min, plain.stand.plot.x_min);
  EXPECT_DOUBLE_EQ(plain.stand_light().plot_x_max, plain.stand.plot.x_max);
  EXPECT_DOUBLE_EQ(plain.stand_light().plot_y_max, plain.stand.plot.y_max);
  const Scenario own = load_scenario(write_scenario(
      "light-domain-own", minimal_stand + "[light]\nperiodic = true\nplot_x_min = -5\nplot_y_min = -2\n"
                                          "plot_x_max = 15\nplot_y_max = 12\n"));
  const LightParameters light = own.stand_light();
  EXPECT_DOUBLE_EQ(light.plot_x_min, -5);
  EXPECT_DOUBLE_EQ(light.plot_y_min, -2);
  EXPECT_DOUBLE_EQ(light.plot_x_max, 15);
  EXPECT_DOUBLE_EQ(light.plot_y_max, 12);
  // A scenario built in code, with no domain, gets the plot.
  Scenario in_code = own;
  in_code.light.plot_x_min = in_code.light.plot_x_max = 0;
  EXPECT_DOUBLE_EQ(in_code.stand_light().plot_x_max, own.stand.plot.x_max);
}

TEST(LoadScenario, RunSpeciesAndLightOverrides) {
  const auto file = write_scenario("overrides", minimal_stand +
                                                    "seed = 42\n"
                                                    "output_interval = 5\n"
                                                    "device = \"opencl:1\"\n"
                                                    "[species.todomatsu]\n"
                                                    "site_asymptote_m = 25\n"
                                                    "max_order = 2\n"
                                                    "activity = -3.5\n"
                                                    "[light]\n"
                                                    "sky_bands = 8\n"
                                                    "exact = true\n"
                                                    "cutoff_m = 6.5\n"
                                                    "far_field_bias_correction = true\n");
  const Scenario s = load_scenario(file);
  EXPECT_EQ(s.run.seed, 42u);
  EXPECT_EQ(s.run.output_interval_years, 5);
  EXPECT_EQ(s.run.device, (DeviceChoice{DeviceChoice::Kind::opencl, 1}));
  const SpeciesParameters& t = s.species.at("todomatsu");
  EXPECT_EQ(t.name, "todomatsu");
  EXPECT_DOUBLE_EQ(t.site_asymptote_m, 25.0);  // an integer is a valid number
  EXPECT_EQ(t.max_order, 2);
  EXPECT_DOUBLE_EQ(t.activity, -3.5);
  EXPECT_DOUBLE_EQ(t.height_k, 0.0348);        // untouched fields keep the defaults
  EXPECT_EQ(s.light.sky_bands, 8);
  EXPECT_TRUE(s.light.exact);
  EXPECT_DOUBLE_EQ(s.light.cutoff_m, 6.5);
  EXPECT_TRUE(s.light.far_field_bias_correction);
  EXPECT_EQ(s.light.sky_sectors, 32);
}

TEST(LoadScenario, DefaultSpeciesIsTheFirstTableInTheFileUnlessNamed) {
  // "ezomatsu" sorts first by name but comes second in the file.
  const std::string species = "[species.todomatsu]\n[species.ezomatsu]\nannual_droop_deg = 1.5\n";
  const Scenario first = load_scenario(write_scenario("first_species", minimal_stand + species));
  EXPECT_EQ(first.stand.default_species, "todomatsu");
  EXPECT_EQ(first.survey.trees[0].species, "todomatsu");
  EXPECT_DOUBLE_EQ(first.species.at("ezomatsu").annual_droop_deg, 1.5);

  std::string named = minimal_stand;
  named.insert(named.find("[run]"), "default_species = \"ezomatsu\"\n");
  const Scenario second = load_scenario(write_scenario("named_species", named + species));
  EXPECT_EQ(second.stand.default_species, "ezomatsu");
  EXPECT_EQ(second.survey.trees[0].species, "ezomatsu");
}

TEST(LoadScenario, ThinningEventsAreSortedByAgeAndIdsMayBeIntegers) {
  const auto file = write_scenario("thinning", minimal_stand +
                                                   "[[thinning]]\nage = 28\nmethod = \"from_above\"\n"
                                                   "target_basal_area_m2_per_ha = 20\n"
                                                   "[[thinning]]\nage = 22\nmethod = \"ids\"\nids = [2, \"3\"]\n"
                                                   "reason = \"crop-tree release\"\n");
  const Scenario s = load_scenario(file);
  ASSERT_EQ(s.thinning.size(), 2u);
  EXPECT_EQ(s.thinning[0].when.stand_age, 22);
  EXPECT_EQ(s.thinning[0].rule.method, ThinningMethod::ids);
  EXPECT_THAT(s.thinning[0].rule.ids, ::testing::ElementsAre("2", "3"));
  EXPECT_EQ(s.thinning[0].reason, "crop-tree release");
  EXPECT_EQ(s.thinning[0].line, 15);  // its [[thinning]] header
  EXPECT_EQ(s.thinning[1].when.stand_age, 28);
  EXPECT_EQ(s.thinning[1].rule.method, ThinningMethod::from_above);
  EXPECT_EQ(s.thinning[1].rule.target_basal_area_m2_per_ha, 20.0);
  EXPECT_FALSE(s.thinning[1].rule.target_stems_per_ha);
  EXPECT_EQ(s.thinning[1].reason, "thinning");
}

TEST(LoadScenario, CommandLineOverrides) {
  std::string toml = minimal_stand + "[[thinning]]\nage = 27\nmethod = \"ids\"\nids = [\"1\"]\n";
  Scenario s = load_scenario(write_scenario("overrides_cli", toml));
  s.set_seed(99);
  EXPECT_EQ(s.run.seed, 99u);
  s.set_years(7);  // ends at age 27: the thinning still happens
  EXPECT_EQ(s.final_age_years(), 27);
  try {
    s.set_years(5);
    FAIL() << "a run ending before a thinning must be refused";
  } catch (const InputError& error) {
    ASSERT_EQ(error.problems().size(), 1u);
    EXPECT_EQ(error.problems()[0].format("key"),
              s.file.string() + ":11: key 'run.years': --years 5 ends the run at stand age 25, before the thinning at age 27");
  }
  EXPECT_EQ(s.run.years, 7);  // unchanged after the refusal
}

TEST(ThinningArithmetic, StemTargetsKeepTheFloorOfTargetTimesArea) {
  // The example stand: 0.048 ha (24 m x 20 m).
  EXPECT_EQ(trees_kept_for_stem_target(980, 0.048), 47);   // 47.04
  EXPECT_EQ(trees_kept_for_stem_target(670, 0.048), 32);   // 32.16
  EXPECT_EQ(trees_kept_for_stem_target(1000, 0.048), 48);  // exactly 48: not 47 by rounding
  EXPECT_EQ(trees_kept_for_stem_target(999, 0.048), 47);   // 47.952
}

TEST(ExampleStands, SobetsuLoadsWithItsThirtyTreeThinning) {
  const Scenario s = load_scenario(stands / "sobetsu" / "scenario.toml");
  EXPECT_EQ(s.survey.trees.size(), 62u);
  EXPECT_TRUE(s.survey.warnings.empty());
  EXPECT_DOUBLE_EQ(s.plot_area_ha(), 0.048);
  EXPECT_EQ(s.stand.age_at_survey_years, 35);
  EXPECT_EQ(s.final_age_years(), 65);
  EXPECT_EQ(s.run.output_interval_years, 5);
  EXPECT_TRUE(s.light.periodic);
  ASSERT_EQ(s.thinning.size(), 2u);
  // 62 trees -> keep 47 (15 removed) -> keep 32 (15 removed): 30 in all.
  const int first_kept = trees_kept_for_stem_target(*s.thinning[0].rule.target_stems_per_ha, s.plot_area_ha());
  const int second_kept = trees_kept_for_stem_target(*s.thinning[1].rule.target_stems_per_ha, s.plot_area_ha());
  EXPECT_EQ(62 - first_kept, 15);
  EXPECT_EQ(first_kept - second_kept, 15);
  // The survey stays within the documented ranges of a 35-year Todomatsu plantation.
  for (const auto& tree : s.survey.trees) {
    EXPECT_GE(tree.height_m, 14.0);
    EXPECT_LE(tree.height_m, 18.0);
    EXPECT_GE(tree.dbh_cm, 16.0);
    EXPECT_LE(tree.dbh_cm, 26.0);
    EXPECT_GE(tree.crown_radius_m, 1.2);
    EXPECT_LE(tree.crown_radius_m, 2.2);
    EXPECT_GE(tree.crown_base_m, 6.0);
    EXPECT_LE(tree.crown_base_m, 9.0);
  }
}

TEST(ExampleStands, TinyLoads) {
  const Scenario s = load_scenario(stands / "tiny" / "scenario.toml");
  EXPECT_EQ(s.survey.trees.size(), 8u);
  EXPECT_EQ(s.run.years, 5);
  ASSERT_EQ(s.thinning.size(), 1u);
  EXPECT_THAT(s.thinning[0].rule.ids, ::testing::ElementsAre("4"));
}

TEST(DeviceChoice, ParsesEveryFormAndPrintsItBack) {
  EXPECT_EQ(DeviceChoice::parse("auto"), DeviceChoice{});
  EXPECT_EQ(DeviceChoice::parse("reference").kind, DeviceChoice::Kind::reference);
  EXPECT_EQ(DeviceChoice::parse("opencl"), (DeviceChoice{DeviceChoice::Kind::opencl, std::nullopt}));
  EXPECT_EQ(DeviceChoice::parse("opencl:0"), (DeviceChoice{DeviceChoice::Kind::opencl, 0}));
  for (const char* text : {"auto", "reference", "opencl", "opencl:12"})
    EXPECT_EQ(DeviceChoice::parse(text).text(), text);
  for (const char* bad : {"gpu", "opencl:", "opencl:-1", "opencl:1x", "OpenCL", "opencl: 1"}) {
    EXPECT_THROW(DeviceChoice::parse(bad), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace heliostand
