#pragma once
// The far-field table's two buffers on an OpenCL device, and whether a device holds them. The OpenCL solver keeps the
// table in two layouts (opencl_light_solver.cpp): the culled kernel's, by cell, within the cap `far_field_table_mb`,
// and the sweep's, a chunk of patches' share of it (swept_layout_bytes). A device allocates no single buffer beyond
// its limit (PoCL on a 24 GiB machine here: 4 GiB), so a cap above it failed at the table's first clCreateBuffer,
// after the stand was established and its tables begun. The solver checks the cap when it is made instead, and says
// the largest cap the device holds.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "compute/compute_backend.hpp"
#include "compute/device_memory.hpp"
#include "light/light_parameters.hpp"

namespace heliostand {

// Entries per cell of the table as the culled kernel reads it: every patch, rounded up to eight (cl/far_field.cl,
// far_field_by_cell). The kernels get it as the build option FAR_ROW.
std::size_t far_row(std::size_t patch_count);

// The sweep's lookups read up to eight floats past a row's last column (cl/voxel_grid.clh, grid_sample_shifted8):
// the density's and the swept table's buffers hold that much more.
inline constexpr std::size_t sweep_overread_floats = 16;

// The sweep fills its own layout a chunk of this many patches at a time and lays each chunk out by cell before the
// next (opencl_light_solver.cpp), so its layout holds one chunk: a quarter of the default 512-patch sky's table. A
// first solve touches that much less fresh memory (docs/performance.md "The far field swept a chunk of patches at a
// time"). A multiple of eight, as the rows are.
inline constexpr std::size_t sweep_chunk_patches = 128;

// The patches of a chunk for a sky of `patch_count` patches: sweep_chunk_patches, or the whole row when it is shorter.
std::size_t sweep_chunk(std::size_t patch_count);

// The sweep's layout for a table by cell of `table_bytes` bytes and a sky of `patch_count` patches: a chunk's share
// of the table's rows (sweep_chunk out of far_row), and the over-read. The solver sizes its buffer and that buffer's
// cap with it, and the device check counts the same bytes.
std::size_t swept_layout_bytes(std::size_t table_bytes, std::size_t patch_count);

// Cells [first, end) of the far field's grid, in the order of its table by cell.
struct CellRun {
  std::size_t first = 0, end = 0;
};

// The runs of consecutive cells that `read` marks (one byte a cell, non-zero where a receiver reads the cell:
// far_field_mark_read in cl/far_field.cl), in order: the parts of the table by cell its layout writes.
std::vector<CellRun> runs_of_cells_read(std::span<const std::uint8_t> read);

// The most the table laid out by cell may take: the far field's budget of cells, with the rows' padding.
std::size_t far_table_cap_bytes(const LightParameters& p, std::size_t patch_count);

// Why a device named `device_name` with `memory` cannot hold both layouts at p.far_field_table_mb, with the largest
// cap it can hold; std::nullopt when it can, and for the exact light, which has no far field.
std::optional<std::string> far_field_beyond_device(const LightParameters& p, const compute::DeviceMemory& memory,
                                                   const std::string& device_name);

// The memory the table may take beyond its default cap, which the fixed share of a run's memory estimate and of the
// light benchmark's already holds (stand/memory_estimate.hpp, light/light_benchmark.hpp): twice the cap above the
// default, as when the sweep's layout held every patch; 0 at or below it, and for the exact light, which has no far
// field. An upper bound: the sweep's layout now holds a chunk's share of the table, and a stand whose table stays
// below the cap takes less.
double far_field_table_bytes_beyond_default(const LightParameters& p);

// That term of the estimates' formulas in words: "twice the far-field table's cap above 512 MB".
std::string far_field_table_memory_term();

// InputError under key 'light.far_field_table_mb' of `file` where `backend`'s device cannot hold the far field at p's
// cap: a run's check before any output (run/simulation.cpp, `bench light --stand`).
void refuse_far_field_beyond_device(const LightParameters& p, const compute::ComputeBackend& backend,
                                    const std::string& file);

// OpenCLLightSolver's constructor throws this with far_field_beyond_device's reason; a run names the scenario's key
// with it first (refuse_far_field_beyond_device).
class FarFieldBeyondDevice : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace heliostand
