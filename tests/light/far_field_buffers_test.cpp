// The far-field table's two buffers against a device's memory (light/far_field_buffers.hpp). PoCL on this 24 GiB
// machine holds 4 GiB a buffer, so a cap above 4294 MB failed at the first solve's clCreateBuffer, after the stand was
// established and its tables begun: the cap is now checked against the device when the solver is made, and the
// refusal names the largest cap that fits. These need no device: the device's figures are given.
#include "light/far_field_buffers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <regex>
#include <string>
#include <utility>
#include <vector>

namespace heliostand {
namespace {

constexpr std::uint64_t gib_bytes = std::uint64_t(1) << 30;
// PoCL 3.1 on the 2-core, 24 GiB EPYC (`clinfo`): 4 GiB a buffer, 11 771 043 840 bytes in all.
constexpr compute::DeviceMemory pocl_here{4 * gib_bytes, 11771043840};

LightParameters culled_at_cap(double cap_mb, int bands = 16, int sectors = 32) {
  LightParameters p;
  p.exact = false;
  p.far_field_table_mb = cap_mb;
  p.sky_bands = bands;
  p.sky_sectors = sectors;
  return p;
}

// The cap a refusal advises ("lower it to N or less"); -1 when it names none.
double advised_cap(const std::string& reason) {
  std::smatch match;
  if (!std::regex_search(reason, match, std::regex("lower it to ([0-9]+) or less"))) return -1;
  return std::stod(match[1]);
}

TEST(FarFieldBuffers, TheLayoutByCellTakesTheCapWithItsRowsPadded) {
  EXPECT_EQ(far_row(512), 512u);
  EXPECT_EQ(far_row(30), 32u);  // a 6 x 5 sky: rows rounded up to eight entries
  EXPECT_EQ(far_table_cap_bytes(culled_at_cap(512), 512), 512'000'000u);
  EXPECT_EQ(far_table_cap_bytes(culled_at_cap(300, 6, 5), 30), 320'000'000u);
}

TEST(FarFieldBuffers, TheDefaultCapFitsTheDeviceHere) {
  const LightParameters at_default = culled_at_cap(LightParameters{}.far_field_table_mb);
  EXPECT_EQ(far_field_beyond_device(at_default, pocl_here, "pocl"), std::nullopt);
}

TEST(FarFieldBuffers, ACapBeyondOneBufferIsRefusedWithTheLargestThatFits) {
  EXPECT_EQ(far_field_beyond_device(culled_at_cap(4294), pocl_here, "pocl"), std::nullopt);  // 4 294 000 064 bytes
  const auto reason = far_field_beyond_device(culled_at_cap(6000), pocl_here, "pocl");
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("a far-field table of up to 6000 MB takes a buffer of up to 6000.0 MB and the sweep's of up "
                         "to 1500.0 MB on the device 'pocl', which holds at most 4294.9 MB a buffer and 11771.0 MB in "
                         "all"),
            std::string::npos)
      << *reason;
  EXPECT_EQ(advised_cap(*reason), 4294) << *reason;
  EXPECT_NE(reason->find("or choose another device (--device, `heliostand devices`)"), std::string::npos) << *reason;
  EXPECT_TRUE(far_field_beyond_device(culled_at_cap(4295), pocl_here, "pocl"));
}

// The sweep's layout holds a chunk of 128 patches (a quarter of the default sky's row) beside the table by cell.
TEST(FarFieldBuffers, BothLayoutsMustFitInTheDevicesMemory) {
  const compute::DeviceMemory wide_buffers{100 * gib_bytes, 8'000'000'000};  // one buffer may take it all; two may not
  EXPECT_EQ(far_field_beyond_device(culled_at_cap(6399), wide_buffers, "gpu"), std::nullopt);
  const auto reason = far_field_beyond_device(culled_at_cap(6500), wide_buffers, "gpu");
  ASSERT_TRUE(reason);
  // 6 400 000 000 bytes by cell, a quarter of that swept, and the over-read do not fit
  EXPECT_EQ(advised_cap(*reason), 6399) << *reason;
}

// The sweep fills its layout a chunk of patches at a time: 128, or a whole row where the sky has fewer patches.
TEST(FarFieldBuffers, TheSweepHoldsAChunkOfTheSkyAtATime) {
  EXPECT_EQ(sweep_chunk(512), 128u);
  EXPECT_EQ(sweep_chunk(130), 128u);  // a 10 x 13 sky: a chunk, then 2 patches and six padding entries
  EXPECT_EQ(sweep_chunk(128), 128u);
  EXPECT_EQ(sweep_chunk(30), 32u);  // a 6 x 5 sky: its row, padding included
  EXPECT_EQ(sweep_chunk(2), 8u);
  // The sweep's layout: a chunk's share of the table's rows and the over-read of sweep_overread_floats floats.
  EXPECT_EQ(swept_layout_bytes(512'000'000, 512), 128'000'064u);  // the default cap: a quarter
  EXPECT_EQ(swept_layout_bytes(136 * 4 * 1000, 130), 128 * 4 * 1000 + 64u);  // 1000 cells of a 10 x 13 sky
  EXPECT_EQ(swept_layout_bytes(32 * 4 * 10, 30), 32 * 4 * 10 + 64u);  // a 6 x 5 sky: the whole table
}

// The rows of the table by cell that the layout writes, and that are made resident before it (opencl_light_solver.cpp):
// the runs of consecutive cells a receiver reads, in order, whatever marks them.
TEST(FarFieldBuffers, TheRowsMadeResidentAreTheRunsOfCellsRead) {
  const auto runs = [](std::vector<std::uint8_t> read) {
    std::vector<std::pair<std::size_t, std::size_t>> found;
    for (const CellRun& run : runs_of_cells_read(read)) found.emplace_back(run.first, run.end);
    return found;
  };
  using Runs = std::vector<std::pair<std::size_t, std::size_t>>;
  EXPECT_EQ(runs({0, 1, 1, 0, 1, 0, 0, 2, 1, 1}), (Runs{{1, 3}, {4, 5}, {7, 10}}));
  EXPECT_EQ(runs({1, 1, 1}), (Runs{{0, 3}}));
  EXPECT_EQ(runs({0, 0, 0}), Runs{});
  EXPECT_EQ(runs({}), Runs{});
}

// Whatever the device and the sky, the advised cap fits and one MB more does not.
TEST(FarFieldBuffers, TheAdvisedCapIsTheLargestThatFits) {
  const compute::DeviceMemory devices[] = {pocl_here,
                                           {256 * (std::uint64_t(1) << 20), gib_bytes},
                                           {4 * gib_bytes, 6 * gib_bytes},
                                           {35'000'000'000, 150'000'000'000},
                                           {1'000'000'064, 2'000'000'128},
                                           {1'000'000'063, 2'000'000'128}};
  const int skies[][2] = {{16, 32}, {8, 16}, {6, 5}, {2, 1}};
  for (const auto& device : devices)
    for (const auto& sky : skies) {
      const auto reason = far_field_beyond_device(culled_at_cap(1e6, sky[0], sky[1]), device, "d");
      ASSERT_TRUE(reason);
      const double largest = advised_cap(*reason);
      ASSERT_GE(largest, 1) << *reason;
      EXPECT_EQ(far_field_beyond_device(culled_at_cap(largest, sky[0], sky[1]), device, "d"), std::nullopt)
          << device.buffer_bytes << " " << sky[0] << "x" << sky[1];
      EXPECT_TRUE(far_field_beyond_device(culled_at_cap(largest + 1, sky[0], sky[1]), device, "d"))
          << device.buffer_bytes << " " << sky[0] << "x" << sky[1];
    }
}

TEST(FarFieldBuffers, ADeviceTooSmallForAnyCapIsToldToChooseAnother) {
  const auto reason = far_field_beyond_device(culled_at_cap(1), {500'000, 1'000'000}, "tiny");
  ASSERT_TRUE(reason);
  EXPECT_EQ(advised_cap(*reason), -1) << *reason;
  EXPECT_NE(reason->find(": choose another device (--device"), std::string::npos) << *reason;
}

TEST(FarFieldBuffers, TheExactLightHasNoFarFieldToHold) {
  LightParameters exact = culled_at_cap(1e6);
  exact.exact = true;
  EXPECT_EQ(far_field_beyond_device(exact, {1, 1}, "tiny"), std::nullopt);
}

}  // namespace
}  // namespace heliostand
