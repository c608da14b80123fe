#pragma once
// The surveyed plot: an axis-aligned rectangle in stand coordinates (metres). Every surveyed tree stands
// inside it; stand densities (stems/ha, basal area/ha) are per its area.
namespace heliostand {

struct PlotBounds {
  double x_min = 0, y_min = 0, x_max = 0, y_max = 0;  // m

  double width_m() const { return x_max - x_min; }
  double depth_m() const { return y_max - y_min; }
  double area_m2() const { return width_m() * depth_m(); }
  double area_ha() const { return area_m2() / 10'000.0; }
  // Edges belong to the plot: a tree surveyed on the boundary line is inside.
  bool contains(double x, double y) const { return x >= x_min && x <= x_max && y >= y_min && y <= y_max; }
};

}  // namespace heliostand
