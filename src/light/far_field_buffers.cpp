#include "light/far_field_buffers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "light/far_field.hpp"

namespace heliostand {
namespace {

constexpr double bytes_per_mb = 1e6;  // far_field_table_mb's unit
constexpr double default_cap_mb = LightParameters{}.far_field_table_mb;
constexpr double table_layouts = 2;  // the estimates' bound: the sweep's and the culled kernel's, each at the cap

// A device's figure in MB, rounded down: the cap a user may take from the message must fit.
double megabytes_down(std::uint64_t bytes) { return std::floor(double(bytes) / (bytes_per_mb / 10)) / 10; }

std::size_t patch_count(const LightParameters& p) { return std::size_t(p.sky_bands) * std::size_t(p.sky_sectors); }

// Both layouts at `cap_mb` on `memory`: each within one buffer, the two together within the device's memory.
bool layouts_fit(const LightParameters& p, double cap_mb, const compute::DeviceMemory& memory) {
  LightParameters at_cap = p;
  at_cap.far_field_table_mb = cap_mb;
  const std::uint64_t layout = far_table_cap_bytes(at_cap, patch_count(p));
  const std::uint64_t swept = swept_layout_bytes(layout, patch_count(p));
  return std::max(layout, swept) <= memory.buffer_bytes && layout + swept <= memory.total_bytes;
}

// The largest whole number of MB whose layouts fit; 0 when not even 1 MB does.
double largest_cap_mb(const LightParameters& p, const compute::DeviceMemory& memory) {
  const double row = double(far_row(patch_count(p)));
  const double both = 1 + double(sweep_chunk(patch_count(p))) / row;  // bytes of the two layouts a byte of the table's
  const double room = std::min(double(memory.buffer_bytes), double(memory.total_bytes) / both);
  const double padding = row / double(patch_count(p));  // bytes of layout a byte of cap
  double cap = std::floor(room / padding / bytes_per_mb);
  while (cap >= 1 && !layouts_fit(p, cap, memory)) cap -= 1;  // the over-read and rounding, a step or two at most
  return std::max(cap, 0.0);
}

}  // namespace

std::size_t far_row(std::size_t patch_count) { return (patch_count + 7) / 8 * 8; }

std::size_t sweep_chunk(std::size_t patch_count) { return std::min(sweep_chunk_patches, far_row(patch_count)); }

std::size_t swept_layout_bytes(std::size_t table_bytes, std::size_t patch_count) {
  return table_bytes / far_row(patch_count) * sweep_chunk(patch_count) + sweep_overread_floats * sizeof(float);
}

std::size_t far_table_cap_bytes(const LightParameters& p, std::size_t patch_count) {
  return std::size_t(far_field_table_budget_cells(p, patch_count) * double(far_row(patch_count)) * sizeof(float));
}

std::vector<CellRun> runs_of_cells_read(std::span<const std::uint8_t> read) {
  std::vector<CellRun> runs;
  for (std::size_t cell = 0; cell < read.size(); ++cell) {
    if (read[cell] == 0) continue;
    if (!runs.empty() && runs.back().end == cell)
      ++runs.back().end;
    else
      runs.push_back({cell, cell + 1});
  }
  return runs;
}

std::optional<std::string> far_field_beyond_device(const LightParameters& p, const compute::DeviceMemory& memory,
                                                   const std::string& device_name) {
  if (p.exact || layouts_fit(p, p.far_field_table_mb, memory)) return std::nullopt;
  const double largest = largest_cap_mb(p, memory);
  const std::string advice =
      largest >= 1 ? fmt::format("lower it to {} or less (a stand whose table stays within that grows the same; a "
                                 "larger one gets coarser cells), or choose another device",
                                 largest)
                   : std::string("choose another device");
  const std::uint64_t layout = far_table_cap_bytes(p, patch_count(p));
  const std::uint64_t swept = swept_layout_bytes(layout, patch_count(p));
  return fmt::format("a far-field table of up to {} MB takes a buffer of up to {:.1f} MB and the sweep's of up to "
                     "{:.1f} MB on the device '{}', which holds at most {:.1f} MB a buffer and {:.1f} MB in all "
                     "(CL_DEVICE_MAX_MEM_ALLOC_SIZE, CL_DEVICE_GLOBAL_MEM_SIZE): {} (--device, `heliostand devices`)",
                     p.far_field_table_mb, double(layout) / bytes_per_mb, double(swept) / bytes_per_mb,
                     device_name, megabytes_down(memory.buffer_bytes), megabytes_down(memory.total_bytes), advice);
}

double far_field_table_bytes_beyond_default(const LightParameters& p) {
  if (p.exact || p.far_field_table_mb <= default_cap_mb) return 0;
  return table_layouts * (p.far_field_table_mb - default_cap_mb) * bytes_per_mb;
}

std::string far_field_table_memory_term() {
  return fmt::format("twice the far-field table's cap above {:g} MB", default_cap_mb);
}

void refuse_far_field_beyond_device(const LightParameters& p, const compute::ComputeBackend& backend,
                                    const std::string& file) {
  const auto memory = backend.memory();
  if (!memory) return;
  if (auto reason = far_field_beyond_device(p, *memory, backend.name()))
    throw InputError({{file, 0, "light.far_field_table_mb", *reason}}, "key");
}

}  // namespace heliostand
