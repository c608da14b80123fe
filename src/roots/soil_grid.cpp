#include "roots/soil_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>

namespace heliostand::roots {

SoilGrid::SoilGrid(const SoilGridGeometry& geometry, double moisture, double nutrient) : geometry_(geometry) {
  if (!(geometry.spacing_m > 0.0)) throw std::invalid_argument("soil grid: spacing must be > 0");
  if (geometry.cells.x < 1 || geometry.cells.y < 1 || geometry.cells.z < 1)
    throw std::invalid_argument("soil grid: need at least one cell along every axis");
  fields_[0].assign(vertex_count(), moisture);
  fields_[1].assign(vertex_count(), nutrient);
  capacity_ = fields_;
}

std::size_t SoilGrid::vertex_count() const {
  const glm::ivec3 n = vertex_counts();
  return static_cast<std::size_t>(n.x) * n.y * n.z;
}

glm::dvec3 SoilGrid::max_corner() const { return geometry_.origin + glm::dvec3(geometry_.cells) * geometry_.spacing_m; }

bool SoilGrid::contains(const glm::dvec3& point) const {
  const glm::dvec3 low = min_corner(), high = max_corner();
  return point.x >= low.x && point.y >= low.y && point.z >= low.z && point.x <= high.x && point.y <= high.y &&
         point.z <= high.z;
}

glm::dvec3 SoilGrid::vertex_position(int i, int j, int k) const {
  return geometry_.origin + glm::dvec3(i, j, k) * geometry_.spacing_m;
}

std::size_t SoilGrid::vertex_index(int i, int j, int k) const {
  const glm::ivec3 n = vertex_counts();
  return static_cast<std::size_t>(i) + static_cast<std::size_t>(n.x) * (j + static_cast<std::size_t>(n.y) * k);
}

double& SoilGrid::at(SoilField field, int i, int j, int k) { return values(field)[vertex_index(i, j, k)]; }
double SoilGrid::at(SoilField field, int i, int j, int k) const { return values(field)[vertex_index(i, j, k)]; }

std::array<SoilGrid::Corner, 8> SoilGrid::corners(const glm::dvec3& point) const {
  // Grid coordinates, clamped to the grid so outside points read the nearest boundary value.
  const glm::dvec3 cells(geometry_.cells);
  const glm::dvec3 g = glm::clamp((point - geometry_.origin) / geometry_.spacing_m, glm::dvec3(0.0), cells);
  const glm::ivec3 base = glm::min(glm::ivec3(glm::floor(g)), geometry_.cells - 1);
  const glm::dvec3 f = g - glm::dvec3(base);
  std::array<Corner, 8> result;
  for (int c = 0; c < 8; ++c) {
    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
    const double weight = (di ? f.x : 1.0 - f.x) * (dj ? f.y : 1.0 - f.y) * (dk ? f.z : 1.0 - f.z);
    result[c] = {vertex_index(base.x + di, base.y + dj, base.z + dk), weight};
  }
  return result;
}

double SoilGrid::value(SoilField field, const glm::dvec3& point) const {
  const std::vector<double>& v = values(field);
  double sum = 0.0;
  for (const Corner& corner : corners(point)) sum += corner.weight * v[corner.index];
  return sum;
}

void SoilGrid::fill_uniform(SoilField field, double value) {
  std::ranges::fill(values(field), value);
  set_capacity_to_current(field);
}

void SoilGrid::fill_gradient(SoilField field, int axis, double at_min, double at_max) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("soil grid: gradient axis must be 0, 1 or 2");
  const glm::ivec3 n = vertex_counts();
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) {
        const double t = static_cast<double>(glm::ivec3(i, j, k)[axis]) / geometry_.cells[axis];
        at(field, i, j, k) = at_min + (at_max - at_min) * t;
      }
  set_capacity_to_current(field);
}

void SoilGrid::fill_layers(SoilField field, const std::vector<double>& bottoms_m, const std::vector<double>& layer_values) {
  if (bottoms_m.size() != layer_values.size() || layer_values.empty())
    throw std::invalid_argument("soil grid: need one value per layer bottom, at least one layer");
  if (!std::ranges::is_sorted(bottoms_m)) throw std::invalid_argument("soil grid: layer bottoms must increase with depth");
  const glm::ivec3 n = vertex_counts();
  for (int k = 0; k < n.z; ++k) {
    const double depth = surface_z() - vertex_position(0, 0, k).z;
    const auto layer = std::ranges::lower_bound(bottoms_m, depth - 1e-12) - bottoms_m.begin();
    const double value = layer_values[std::min<std::size_t>(layer, layer_values.size() - 1)];
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) at(field, i, j, k) = value;
  }
  set_capacity_to_current(field);
}

SoilGrid::DepletionShares SoilGrid::depletion_shares(const glm::dvec3& point, double fraction) const {
  const std::array<Corner, 8> around = corners(point);
  DepletionShares shares;
  for (std::size_t c = 0; c < around.size(); ++c)
    shares[c] = {around[c].index, std::clamp(fraction * around[c].weight, 0.0, 1.0)};
  return shares;
}

double SoilGrid::deplete(SoilField field, const glm::dvec3& point, double fraction) {
  return deplete(field, depletion_shares(point, fraction));
}

double SoilGrid::deplete(SoilField field, const DepletionShares& shares) {
  std::vector<double>& v = values(field);
  double removed = 0.0;
  for (const VertexShare& vertex : shares) {
    const double take = vertex.share * v[vertex.index];
    v[vertex.index] -= take;
    removed += take;
  }
  return removed;
}

void SoilGrid::recharge(const SoilRecharge& recharge, double years) {
  // Exponential approach, so that several years at once equal the same years one by one.
  auto relax = [years](std::vector<double>& v, const std::vector<double>& target, double rate) {
    const double keep = std::pow(1.0 - std::clamp(rate, 0.0, 1.0), years);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = target[i] + (v[i] - target[i]) * keep;
  };
  relax(values(SoilField::moisture), capacity(SoilField::moisture), recharge.moisture_rate);
  relax(values(SoilField::nutrient), capacity(SoilField::nutrient), recharge.nutrient_rate);
}

}  // namespace heliostand::roots
