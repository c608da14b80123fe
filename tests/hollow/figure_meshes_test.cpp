// Writes meshes like the seed's Figs. 4.1–4.4 as VTK XML PolyData into <build>/validation/hollows/, to be
// rendered later (see validation/hollows/README.md), and checks that each file reads back whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "hollow/broken_stem.hpp"
#include "hollow/hollow_mesh.hpp"
#include "io/hollow_vtp_writer.hpp"

namespace heliostand::hollow {
namespace {

struct Figure {
  std::string name;
  double w, h, r, i;
  double height = 1.5;
  double azimuth = 0.0;
  double flare = 0.0;
  Placement placement = Placement::cylindrical;
};

// Fig. 4.1/4.2: outlines from tall-narrow to wide-flat (callus thickness and bark detour change with them);
// Fig. 4.3: a thick roll with large bulge, the bark rising onto it; Fig. 4.4: hollows on a whole stem,
// including the seed's own placement and our extensions (wide wound, root collar).
const Figure figures[] = {
    {"fig4_1_tall_narrow", 0.06, 0.30, 0.012, 0.003},
    {"fig4_1_round", 0.16, 0.16, 0.015, 0.025},
    {"fig4_1_wide_flat", 0.30, 0.08, 0.015, 0.04},
    {"fig4_2_bark_detour", 0.14, 0.24, 0.015, 0.015},
    {"fig4_3_thick_roll", 0.20, 0.30, 0.02, 0.03},
    {"fig4_4_seed_tangent_plane", 0.20, 0.28, 0.015, 0.02, 3.0, 45.0, 0.0, Placement::tangent_plane},
    {"fig4_4_wide_wrapping", 0.95, 0.30, 0.02, 0.04, 2.0, 90.0},
    {"fig4_4_root_collar", 0.22, 0.30, 0.02, 0.02, 0.42, 180.0, 0.6},
};

TEST(FigureMeshes, WriteSeedLikeFiguresAsVtp) {
  const std::filesystem::path out = std::filesystem::path(HELIOSTAND_BINARY_DIR) / "validation" / "hollows";
  std::filesystem::create_directories(out);
  for (const Figure& f : figures) {
    const TrunkSurface trunk = TrunkSurface::seed001_taper(30.0, 15.0, {f.flare, 0.3});
    HollowSpec spec;
    spec.width_m = f.w;
    spec.wound_height_m = f.h;
    spec.callus_radius_m = f.r;
    spec.bulge_m = f.i;
    spec.height_m = f.height;
    spec.azimuth_deg = f.azimuth;
    spec.placement = f.placement;
    spec.seed = 2024;
    const auto problems = validate(spec, trunk);
    ASSERT_TRUE(problems.empty()) << f.name << ": " << problems[0].field << ": " << problems[0].reason;
    const HollowModel model = build_hollow(spec, trunk);
    const std::string path = (out / (f.name + ".vtp")).string();
    write_vtp(model.mesh, path);

    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    EXPECT_EQ(poly->GetNumberOfPoints(), static_cast<vtkIdType>(model.mesh.vertices.size())) << f.name;
    EXPECT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(model.mesh.triangles.size())) << f.name;
    for (const char* array : {"part", "callus_thickness_m", "bark_shift_m", "bark_lift_m", "bark_line"})
      EXPECT_NE(poly->GetPointData()->GetArray(array), nullptr) << f.name << " lacks " << array;
  }
  // Beyond the seed: a hollow all around a broken stem (oblique break).
  BrokenStemSpec broken;
  broken.break_height_m = 4.0;
  broken.break_tilt_m = 0.25;
  broken.callus_radius_m = 0.03;
  broken.bulge_m = 0.02;
  broken.seed = 2024;
  write_vtp(build_broken_stem(broken, TrunkSurface::seed001_taper(30.0, 15.0)).mesh,
            (out / "beyond_broken_stem_ring.vtp").string());
  EXPECT_TRUE(std::filesystem::exists(out / "beyond_broken_stem_ring.vtp"));
  // Beyond the seed: two hollows on one stem, one above the other (build_stem_with_hollows).
  HollowSpec low, high;
  low.height_m = 1.2, low.azimuth_deg = -20.0, low.width_m = 0.14, low.wound_height_m = 0.24, low.seed = 2024;
  high.height_m = 1.9, high.azimuth_deg = 40.0, high.width_m = 0.20, high.wound_height_m = 0.30;
  high.callus_radius_m = 0.02, high.bulge_m = 0.03, high.seed = 2025;
  const TrunkSurface stacked_trunk = TrunkSurface::seed001_taper(30.0, 15.0);
  ASSERT_TRUE(validate_hollows({low, high}, stacked_trunk).empty());
  write_vtp(build_stem_with_hollows({low, high}, stacked_trunk), (out / "beyond_two_hollows.vtp").string());
  EXPECT_TRUE(std::filesystem::exists(out / "beyond_two_hollows.vtp"));
  // A stem without a hollow, for comparison.
  write_vtp(build_trunk_mesh(TrunkSurface::seed001_taper(30.0, 15.0)), (out / "stem_without_hollow.vtp").string());
  EXPECT_TRUE(std::filesystem::exists(out / "stem_without_hollow.vtp"));
}

}  // namespace
}  // namespace heliostand::hollow
