#pragma once
// The soil under the whole stand (seed 003): a voxel grid with moisture and a nutrient level stored at
// the voxel vertices, read anywhere by trilinear interpolation. Uptake by root tips depletes it; a
// yearly recharge moves every vertex back toward field capacity.
//
// Moisture and nutrient are relative levels: 0 = dry / none, 1 = saturated / the reference fertility
// (seed 003 uses 0.5 for poor and 1.0 for rich soil). The grid's top face is the soil surface.
// Every vertex also keeps its capacity — the level the site returns to (field capacity for moisture):
// the fill_* functions and the soil file set value and capacity together; uptake lowers only the value;
// recharge moves the value back toward the capacity, so a dry slope stays dry and a wet hollow wet.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

namespace heliostand::roots {

enum class SoilField { moisture = 0, nutrient = 1 };

struct SoilGridGeometry {
  glm::dvec3 origin{0.0};        // m, the bottom-south-west corner (min x, min y, min z)
  double spacing_m = 0.25;       // voxel edge length
  glm::ivec3 cells{1, 1, 1};     // voxels along x, y, z (vertices = cells + 1)
};

struct SoilRecharge {
  double moisture_rate = 0.8;    // fraction of the moisture deficit (capacity − value) restored per year
  double nutrient_rate = 0.3;    // fraction of the nutrient deficit restored per year
};

class SoilGrid {
 public:
  // Throws std::invalid_argument for non-positive spacing or cell counts.
  SoilGrid(const SoilGridGeometry& geometry, double moisture, double nutrient);

  const SoilGridGeometry& geometry() const { return geometry_; }
  glm::ivec3 vertex_counts() const { return geometry_.cells + 1; }
  std::size_t vertex_count() const;
  double surface_z() const { return geometry_.origin.z + geometry_.cells.z * geometry_.spacing_m; }
  glm::dvec3 min_corner() const { return geometry_.origin; }
  glm::dvec3 max_corner() const;
  bool contains(const glm::dvec3& point) const;
  glm::dvec3 vertex_position(int i, int j, int k) const;

  // Trilinear interpolation; points outside the grid read the value at the nearest point of the grid.
  double value(SoilField field, const glm::dvec3& point) const;
  double moisture(const glm::dvec3& point) const { return value(SoilField::moisture, point); }
  double nutrient(const glm::dvec3& point) const { return value(SoilField::nutrient, point); }

  double& at(SoilField field, int i, int j, int k);
  double at(SoilField field, int i, int j, int k) const;
  const std::vector<double>& values(SoilField field) const { return fields_[static_cast<int>(field)]; }
  std::vector<double>& values(SoilField field) { return fields_[static_cast<int>(field)]; }
  const std::vector<double>& capacity(SoilField field) const { return capacity_[static_cast<int>(field)]; }
  // The current values become the capacity (after editing values by hand).
  void set_capacity_to_current(SoilField field) { capacity_[static_cast<int>(field)] = values(field); }
  std::size_t vertex_index(int i, int j, int k) const;

  // Initial fields (value and capacity).
  void fill_uniform(SoilField field, double value);
  // Linear from `at_min` on the grid's min face to `at_max` on its max face along axis 0=x, 1=y, 2=z.
  void fill_gradient(SoilField field, int axis, double at_min, double at_max);
  // Horizontal layers by depth below the surface: layer n holds `values[n]` from depth
  // `bottoms_m[n-1]` down to `bottoms_m[n]` (vertices below the last bottom take the last value).
  void fill_layers(SoilField field, const std::vector<double>& bottoms_m, const std::vector<double>& values);

  // What a depletion at a point takes of each of the 8 vertices around it: min(1, fraction × trilinear weight)
  // of the vertex's current value. It reads only the grid's geometry, so the shares of many points can be
  // found at once (in parallel) and taken afterwards, in order.
  struct VertexShare {
    std::size_t index;
    double share;
  };
  using DepletionShares = std::array<VertexShare, 8>;
  DepletionShares depletion_shares(const glm::dvec3& point, double fraction) const;

  // Removes `fraction_per_vertex × weight × current value` from the 8 vertices around `point`
  // (trilinear weights), never below 0. Returns the amount removed (sum over vertices).
  double deplete(SoilField field, const glm::dvec3& point, double fraction);
  // The same with the shares found beforehand: the same amounts, bit for bit.
  double deplete(SoilField field, const DepletionShares& shares);

  // Recharge: value += rate · (capacity − value) per year at every vertex (compounded over `years`).
  void recharge(const SoilRecharge& recharge, double years = 1.0);

 private:
  struct Corner {
    std::size_t index;
    double weight;
  };
  std::array<Corner, 8> corners(const glm::dvec3& point) const;

  SoilGridGeometry geometry_;
  std::array<std::vector<double>, 2> fields_;
  std::array<std::vector<double>, 2> capacity_;
};

}  // namespace heliostand::roots
