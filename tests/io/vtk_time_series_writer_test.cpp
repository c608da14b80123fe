#include "io/vtk_time_series_writer.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <optional>
#include <regex>
#include <string>
#include <utility>

#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "io/file_size_limit.hpp"
#include "io/read_multiblock.hpp"
#include "io/synthetic_stand.hpp"
#include "io/temp_folder.hpp"
#include "io/vtk_numbers.hpp"
#include "read_text.hpp"

namespace heliostand {
namespace {
namespace fs = std::filesystem;

using testing::read_multiblock;

vtkPolyData* block_named(vtkMultiBlockDataSet& multiblock, const std::string& name) {
  for (unsigned i = 0; i < multiblock.GetNumberOfBlocks(); ++i) {
    if (multiblock.HasMetaData(i) && name == multiblock.GetMetaData(i)->Get(vtkCompositeDataSet::NAME())) {
      return vtkPolyData::SafeDownCast(multiblock.GetBlock(i));
    }
  }
  return nullptr;
}

double time_value(vtkDataObject& object) {
  vtkDataArray* array = object.GetFieldData() ? object.GetFieldData()->GetArray("TimeValue") : nullptr;
  return array && array->GetNumberOfTuples() == 1 ? array->GetTuple1(0) : -1.0;
}

struct PvdEntry {
  double timestep;
  std::string file;
};

std::vector<PvdEntry> parse_pvd(const fs::path& pvd) {
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetFileName(pvd.string().c_str());
  if (parser->Parse() != 1) return {};
  vtkXMLDataElement* root = parser->GetRootElement();
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  std::vector<PvdEntry> entries;
  for (int i = 0; collection && i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* dataset = collection->GetNestedElement(i);
    EXPECT_STREQ(dataset->GetName(), "DataSet");
    entries.push_back({std::stod(dataset->GetAttribute("timestep")), dataset->GetAttribute("file")});
  }
  return entries;
}

class VtkTimeSeries : public ::testing::Test {
 protected:
  VtkTimeSeries() : tmp_("vtk_time_series"), folder_(tmp_.path() / "run", false) {}
  testing::TempFolder tmp_;
  OutputFolder folder_;
};

TEST_F(VtkTimeSeries, EachYearIsAMultiblockWithTheThreeNamedBlocks) {
  VtkTimeSeriesWriter writer(folder_);
  const auto stand = testing::make_synthetic_stand(10, 0);
  const fs::path vtm = writer.write_year(stand.snapshot);
  EXPECT_EQ(vtm, fs::path("stand") / "stand_age_0010.vtm");

  auto multiblock = read_multiblock(folder_.path_of(vtm));
  ASSERT_NE(multiblock, nullptr);
  ASSERT_EQ(multiblock->GetNumberOfBlocks(), 3u);
  EXPECT_STREQ(multiblock->GetMetaData(0u)->Get(vtkCompositeDataSet::NAME()), "branches");
  EXPECT_STREQ(multiblock->GetMetaData(1u)->Get(vtkCompositeDataSet::NAME()), "leaf_balls");
  EXPECT_STREQ(multiblock->GetMetaData(2u)->Get(vtkCompositeDataSet::NAME()), "trees");
  for (const char* name : {"branches", "leaf_balls", "trees"}) {
    vtkPolyData* block = block_named(*multiblock, name);
    ASSERT_NE(block, nullptr) << name;
    EXPECT_EQ(time_value(*block), 10.0) << name;
  }
}

TEST_F(VtkTimeSeries, BranchesAreOneLinePerShootWithRadiusAsPointData) {
  VtkTimeSeriesWriter writer(folder_);
  const auto stand = testing::make_synthetic_stand(10, 0);  // heights 6, 5, 4 m
  auto multiblock = read_multiblock(folder_.path_of(writer.write_year(stand.snapshot)));
  vtkPolyData* branches = block_named(*multiblock, "branches");
  ASSERT_NE(branches, nullptr);

  const int shoots = testing::synthetic_shoot_count(6) + testing::synthetic_shoot_count(5) +
                     testing::synthetic_shoot_count(4);
  ASSERT_EQ(shoots, 22 + 17 + 12);
  EXPECT_EQ(branches->GetNumberOfLines(), shoots);
  EXPECT_EQ(branches->GetNumberOfPoints(), 2 * shoots);

  vtkDataArray* radius = branches->GetPointData()->GetArray("radius");
  ASSERT_NE(radius, nullptr) << "radius must be point data for the Tube filter";
  EXPECT_EQ(branches->GetCellData()->GetArray("radius"), nullptr);
  EXPECT_EQ(radius->GetNumberOfTuples(), 2 * shoots);
  EXPECT_DOUBLE_EQ(radius->GetTuple1(0), 0.06);  // tree 1, lowest stem shoot: base radius 0.01 × 6
  EXPECT_DOUBLE_EQ(radius->GetTuple1(1), 0.052); // its tip: 0.01 × 5 + 0.002

  for (const char* name : {"tree_id", "order", "axis", "year_formed", "alive"}) {
    vtkDataArray* array = branches->GetCellData()->GetArray(name);
    ASSERT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), shoots) << name;
  }
  // The lowest whorl of each tree is dead: 4 dead branches per tree.
  vtkDataArray* alive = branches->GetCellData()->GetArray("alive");
  double alive_sum = 0;
  for (vtkIdType i = 0; i < alive->GetNumberOfTuples(); ++i) alive_sum += alive->GetTuple1(i);
  EXPECT_EQ(alive_sum, shoots - 3 * testing::kBranchesPerWhorl);
  vtkDataArray* tree_id = branches->GetCellData()->GetArray("tree_id");
  EXPECT_EQ(tree_id->GetTuple1(0), 1);
  EXPECT_EQ(tree_id->GetTuple1(shoots - 1), 3);
}

TEST_F(VtkTimeSeries, LeafBallsCarryRadiusLightAndTree) {
  VtkTimeSeriesWriter writer(folder_);
  const auto stand = testing::make_synthetic_stand(10, 0);
  auto multiblock = read_multiblock(folder_.path_of(writer.write_year(stand.snapshot)));
  vtkPolyData* balls = block_named(*multiblock, "leaf_balls");
  ASSERT_NE(balls, nullptr);
  const int count = testing::synthetic_ball_count(6) + testing::synthetic_ball_count(5) +
                    testing::synthetic_ball_count(4);
  ASSERT_EQ(count, 12 + 8 + 4);
  EXPECT_EQ(balls->GetNumberOfPoints(), count);
  EXPECT_EQ(balls->GetNumberOfVerts(), count);
  for (const char* name : {"radius", "light", "tree_id"}) {
    vtkDataArray* array = balls->GetPointData()->GetArray(name);
    ASSERT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), count) << name;
  }
  EXPECT_DOUBLE_EQ(balls->GetPointData()->GetArray("radius")->GetTuple1(0), 0.25);
  // First ball of tree 1 sits on the whorl at 3 m: light 0.2 + 0.1 × 3.
  EXPECT_DOUBLE_EQ(balls->GetPointData()->GetArray("light")->GetTuple1(0), 0.5);
  EXPECT_EQ(balls->GetPointData()->GetArray("tree_id")->GetTuple1(count - 1), 3);
}

TEST_F(VtkTimeSeries, LeafBallsCarryTheRelativeLightTheShootRulesRead) {
  VtkTimeSeriesWriter writer(folder_);
  auto stand = testing::make_synthetic_stand(10, 0);
  // Tree 1 gets a relative light per ball; the others none, which must read as NaN, not as a neighbour's value.
  TreeSnapshot& first = stand.snapshot.trees.front();
  for (std::size_t i = 0; i < first.leaf_balls.size(); ++i) first.leaf_ball_relative_light.push_back(0.01 * (i + 1));
  auto multiblock = read_multiblock(folder_.path_of(writer.write_year(stand.snapshot)));
  vtkPolyData* balls = block_named(*multiblock, "leaf_balls");
  ASSERT_NE(balls, nullptr);
  vtkDataArray* relative = balls->GetPointData()->GetArray("relative_light");
  ASSERT_NE(relative, nullptr);
  ASSERT_EQ(relative->GetNumberOfTuples(), balls->GetNumberOfPoints());
  const auto own = static_cast<vtkIdType>(first.leaf_balls.size());
  for (vtkIdType i = 0; i < own; ++i) EXPECT_DOUBLE_EQ(relative->GetTuple1(i), 0.01 * (i + 1)) << i;
  for (vtkIdType i = own; i < relative->GetNumberOfTuples(); ++i) EXPECT_TRUE(std::isnan(relative->GetTuple1(i))) << i;
}

TEST_F(VtkTimeSeries, TreesAreOnePointPerStemBaseWithStatusCodeAndLabel) {
  VtkTimeSeriesWriter writer(folder_);
  auto stand = testing::make_synthetic_stand(10, 0);
  stand.snapshot.trees[1].status = TreeStatus::removed;
  stand.snapshot.trees[2].status = TreeStatus::dead;
  auto multiblock = read_multiblock(folder_.path_of(writer.write_year(stand.snapshot)));
  vtkPolyData* trees = block_named(*multiblock, "trees");
  ASSERT_NE(trees, nullptr);
  ASSERT_EQ(trees->GetNumberOfPoints(), 3);
  double p[3];
  trees->GetPoint(1, p);
  EXPECT_DOUBLE_EQ(p[0], 7.0);
  EXPECT_DOUBLE_EQ(p[1], 3.0);
  for (const char* name : {"tree_id", "status", "age_years", "height_m", "dbh_cm", "crown_base_m",
                           "crown_radius_m", "volume_m3", "mean_light"}) {
    vtkDataArray* array = trees->GetPointData()->GetArray(name);
    ASSERT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), 3) << name;
  }
  vtkDataArray* status = trees->GetPointData()->GetArray("status");
  EXPECT_EQ(status->GetTuple1(0), 0);  // alive
  EXPECT_EQ(status->GetTuple1(1), 2);  // removed
  EXPECT_EQ(status->GetTuple1(2), 1);  // dead
  EXPECT_EQ(trees->GetPointData()->GetArray("height_m")->GetTuple1(0), 6.0);
  EXPECT_EQ(trees->GetPointData()->GetArray("dbh_cm")->GetTuple1(2), 8.0);
  auto* label = vtkStringArray::SafeDownCast(trees->GetPointData()->GetAbstractArray("label"));
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->GetValue(1), "A,2");
}

TEST_F(VtkTimeSeries, PvdIndexesEveryYearByStandAgeAfterEachWrite) {
  VtkTimeSeriesWriter writer(folder_);
  const fs::path pvd = folder_.path_of(VtkTimeSeriesWriter::collection_file);

  const auto first = testing::make_synthetic_stand(10, 0);
  writer.write_year(first.snapshot);
  auto entries = parse_pvd(pvd);  // a run stopped here can already be opened
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].timestep, 10.0);
  EXPECT_EQ(entries[0].file, "stand/stand_age_0010.vtm");

  const auto second = testing::make_synthetic_stand(15, 5);
  writer.write_year(second.snapshot);
  entries = parse_pvd(pvd);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].timestep, 15.0);
  EXPECT_EQ(entries[1].file, "stand/stand_age_0015.vtm");
  for (const PvdEntry& entry : entries) {
    auto multiblock = read_multiblock(pvd.parent_path() / entry.file);
    ASSERT_NE(multiblock, nullptr);
    EXPECT_EQ(time_value(*block_named(*multiblock, "trees")), entry.timestep);
  }
  // The second year has taller trees, hence more shoots.
  auto later = read_multiblock(pvd.parent_path() / entries[1].file);
  EXPECT_EQ(block_named(*later, "branches")->GetNumberOfLines(),
            testing::synthetic_shoot_count(8) + testing::synthetic_shoot_count(7) + testing::synthetic_shoot_count(6));
}

TEST_F(VtkTimeSeries, LeavesNoTemporariesAndRecordsEveryFile) {
  VtkTimeSeriesWriter writer(folder_);
  const auto stand = testing::make_synthetic_stand(10, 0);
  writer.write_year(stand.snapshot);
  writer.write_year(stand.snapshot);  // rewriting a year replaces it cleanly
  for (const auto& entry : fs::recursive_directory_iterator(folder_.root())) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
  const auto& outputs = folder_.output_files();
  for (const std::string& file : outputs) EXPECT_TRUE(fs::is_regular_file(folder_.path_of(file))) << file;
  EXPECT_NE(std::find(outputs.begin(), outputs.end(), "stand.pvd"), outputs.end());
  EXPECT_NE(std::find(outputs.begin(), outputs.end(), "stand/stand_age_0010.vtm"), outputs.end());
  EXPECT_EQ(parse_pvd(folder_.path_of("stand.pvd")).size(), 1u);
}

TEST_F(VtkTimeSeries, AnExtraBlockBuilderAddsANamedBlock) {
  VtkTimeSeriesWriter writer(folder_);
  writer.add_block({"roots", [](const StandSnapshot& snapshot) -> vtkSmartPointer<vtkDataObject> {
                      // A stand-in for a later feature's block: one point per tree.
                      return build_trees_block(snapshot);
                    }});
  const auto stand = testing::make_synthetic_stand(12, 2);
  auto multiblock = read_multiblock(folder_.path_of(writer.write_year(stand.snapshot)));
  ASSERT_EQ(multiblock->GetNumberOfBlocks(), 5u);  // branches, leaf_balls, trees, trunk + roots
  vtkPolyData* roots = block_named(*multiblock, "roots");
  ASSERT_NE(roots, nullptr);
  EXPECT_EQ(time_value(*roots), 12.0);
}

TEST_F(VtkTimeSeries, AYearWithoutTreesIsStillAReadableTimeStep) {
  // VTK 9.1 leaves empty blocks out of the .vtm; the year itself must still be there with its time.
  VtkTimeSeriesWriter writer(folder_);
  StandSnapshot empty;
  empty.stand_age = 60;
  auto multiblock = read_multiblock(folder_.path_of(writer.write_year(empty)));
  ASSERT_NE(multiblock, nullptr);
  EXPECT_EQ(time_value(*multiblock), 60.0);
  const auto entries = parse_pvd(folder_.path_of(VtkTimeSeriesWriter::collection_file));
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].timestep, 60.0);
}

// The compressor a piece file names in its header, as VTK's readers choose their decompressor by it; "" for a piece
// written raw, whose header names none.
std::string piece_compressor(const fs::path& piece) {
  const std::string text = testing::read_text(piece);
  const std::string header = text.substr(0, text.find('>', text.find("<VTKFile")));
  std::smatch compressor;
  return std::regex_search(header, compressor, std::regex(R"re(compressor="([^"]*)")re")) ? compressor[1].str() : "";
}

// run.vtk_compression: every piece of a year names the compressor it was written with (LZ4 unless told otherwise),
// and each compressor gives back the same year, number for number.
TEST_F(VtkTimeSeries, EachCompressionNamesItsCompressorInEveryPieceAndGivesBackTheSameYear) {
  const auto stand = testing::make_synthetic_stand(10, 0);
  std::vector<double> first;
  const std::vector<std::pair<std::optional<VtkCompression>, std::string>> compressions{
      {std::nullopt, "vtkLZ4DataCompressor"},
      {VtkCompression::lz4, "vtkLZ4DataCompressor"},
      {VtkCompression::zlib, "vtkZLibDataCompressor"},
      {VtkCompression::none, ""}};
  for (const auto& [compression, compressor] : compressions) {
    const std::string name = compression ? std::string(name_of(*compression)) : "default";
    OutputFolder folder(tmp_.path() / name, false);
    VtkTimeSeriesWriter writer = compression ? VtkTimeSeriesWriter(folder, default_stand_blocks(), *compression)
                                             : VtkTimeSeriesWriter(folder);
    const fs::path vtm = folder.path_of(writer.write_year(stand.snapshot));
    int pieces = 0;
    for (const auto& piece : fs::directory_iterator(fs::path(vtm).replace_extension())) {
      EXPECT_EQ(piece_compressor(piece.path()), compressor) << name << ": " << piece.path();
      ++pieces;
    }
    EXPECT_EQ(pieces, 3) << name;  // branches, leaf_balls, trees
    const std::vector<double> numbers = testing::numbers_of(*read_multiblock(vtm));
    EXPECT_GT(numbers.size(), 100u) << name;
    if (first.empty()) first = numbers;
    EXPECT_EQ(testing::first_difference(numbers, first), -1) << name;
  }
}

// VTK's writers return success from a write that failed and report it only in their error code: the year must
// still stop the run, with the .vtm's name, and leave nothing of itself behind. A limit of one byte fails the .vtm
// itself (the system's reason); one of 3 000 bytes lets the .vtm (~830 bytes) through but not its pieces (5–7 kB
// with zlib, more with the default LZ4).
TEST_F(VtkTimeSeries, AYearThatCannotBeWrittenIsAnErrorAndLeavesTheSeriesAsItWas) {
  VtkTimeSeriesWriter writer(folder_);
  writer.write_year(testing::make_synthetic_stand(10, 0).snapshot);
  const std::string series_before = testing::read_text(folder_.path_of(VtkTimeSeriesWriter::collection_file));
  const std::string vtm = folder_.path_of("stand/stand_age_0011.vtm").string();
  for (const auto& [bytes, reason] : {std::pair<rlim_t, std::string>{1, std::strerror(EFBIG)},
                                      std::pair<rlim_t, std::string>{3000, "VTK: OutOfDiskSpaceError"}}) {
    std::string message;
    {
      testing::FileSizeLimit full_disk(bytes);
      try {
        writer.write_year(testing::make_synthetic_stand(11, 1).snapshot);
      } catch (const OutputFolderError& e) {
        message = e.what();
      }
    }
    EXPECT_EQ(message, "cannot write " + vtm + ": " + reason) << "files limited to " << bytes << " bytes";
    EXPECT_FALSE(fs::exists(vtm));
    EXPECT_FALSE(fs::exists(folder_.path_of("stand/stand_age_0011")));
    EXPECT_EQ(testing::read_text(folder_.path_of(VtkTimeSeriesWriter::collection_file)), series_before);
    for (const auto& entry : fs::recursive_directory_iterator(folder_.root()))
      EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

}  // namespace
}  // namespace heliostand
