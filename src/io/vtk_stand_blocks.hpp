#pragma once
// The blocks of the yearly VTK multiblock. Each block is built from the StandSnapshot by a named
// builder, so a later feature (roots, soil grid, trunk or hollow meshes) adds a block by adding a
// builder to the list — the writer does not change. Arrays and units: docs/formats.md.
#include <functional>
#include <string>
#include <vector>

#include <vtkDataObject.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "records/stand_snapshot.hpp"
#include "scenario/output_detail.hpp"

namespace heliostand {

using BlockBuilder = std::function<vtkSmartPointer<vtkDataObject>(const StandSnapshot&)>;

struct StandBlock {
  std::string name;     // block name shown in ParaView (vtkCompositeDataSet::NAME)
  BlockBuilder build;
  int age_multiple = 1;  // written only in the output years whose stand age is a multiple of this (roots, soil)

  bool written_at(int stand_age) const { return age_multiple <= 1 || stand_age % age_multiple == 0; }
};

// One two-point line per shoot (base → tip). Point data: radius (m, wood radius, for the Tube filter's
// "Vary Radius: By Absolute Scalar"). Cell data: tree_id, order, axis, year_formed, alive (1/0).
vtkSmartPointer<vtkPolyData> build_branches_block(const StandSnapshot& snapshot);

// One vertex per leaf ball at its centre. Point data: radius (m), light (relative, 0..1; NaN when the
// tree has no light values), tree_id.
vtkSmartPointer<vtkPolyData> build_leaf_balls_block(const StandSnapshot& snapshot);

// One vertex per tree at its stem base. Point data: tree_id, label (survey id), status (TreeStatus code),
// hollow_count, habitat_tree (1 when it carries a hollow), age_years, height_m, dbh_cm, crown_base_m, crown_radius_m, volume_m3, mean_light,
// light_budget, relative_light, dbh_increment_cm.
vtkSmartPointer<vtkPolyData> build_trees_block(const StandSnapshot& snapshot);

// Every standing tree's stem surface (TreeSnapshot::trunk) in stand coordinates, as triangles. Point data:
// tree_id, part (0 stem, 1 bark around a hollow, 2 callus roll), callus_thickness_m, bark_shift_m, bark_lift_m.
vtkSmartPointer<vtkPolyData> build_trunk_block(const StandSnapshot& snapshot);

// branches, leaf_balls, trees, trunk — in that order (detail `full`).
std::vector<StandBlock> default_stand_blocks();

// The blocks of a level of detail (docs/formats.md): full — default_stand_blocks(), crown_envelope and foliage; envelope — trees, stem
// (the stem axis as lines: the stem surface, `trunk`, is 70 kB a tree a year), crown_envelope; cone — trees,
// crown_cone.
std::vector<StandBlock> stand_blocks(OutputDetail detail);

// The multiblock of one output year: one block per builder written at its stand age, each block and the multiblock itself
// carrying the stand age in a one-value field array `TimeValue` (and the run's `year_index`).
vtkSmartPointer<vtkMultiBlockDataSet> build_stand_multiblock(const StandSnapshot& snapshot,
                                                             const std::vector<StandBlock>& blocks);

}  // namespace heliostand
