#pragma once
// One annual root segment: what a root apex adds in one year (seed 003's "root branch" unit).
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "geometry/compass_sector.hpp"
#include "roots/root_type.hpp"

namespace heliostand::roots {

// The 8 paths of seed 003: the compass sectors around the main root (geometry/compass_sector.hpp).
inline constexpr int path_count = compass_sector_count;
inline constexpr int no_sector = -1;  // the main root itself belongs to no single path

struct RootSegment {
  glm::dvec3 start{0.0};        // m, stand coordinates (x east, y north, z up)
  glm::dvec3 end{0.0};          // m
  double radius_m = 0.0;
  RootType type = RootType::main;
  int birth_year = 0;           // year the segment formed (age = year − birth_year)
  int axis_birth_year = 0;      // year this root axis started (growth stops after growth_years)
  int parent = -1;              // index of the parent segment in the tree's list; -1 for the first
  int order = 0;                // 0 the main root, +1 for every new root started (a continuation keeps it)
  std::uint64_t id = 0;         // stable within the tree: names the segment's random streams
  int sector = no_sector;       // path 0..7 where the route of this segment joins the main root
  bool growing = false;         // carries the apex of its axis: elongates and branches next year
  bool alive = true;

  glm::dvec3 direction() const { return glm::normalize(end - start); }
  double length() const { return glm::length(end - start); }
};

}  // namespace heliostand::roots
