#include "light/foliage_clumping.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/parallel_for.hpp"

namespace heliostand {
namespace {

int slab_of(double coordinate, double origin, double cell, int count, bool wraps) {
  const int i = static_cast<int>(std::floor((coordinate - origin) / cell));
  return wraps ? wrap_cell(i, count) : std::clamp(i, 0, count - 1);
}

// The pixels of one row of a face that a ball's disc covers: those whose centre lies within the ball's radius r
// of its centre, ((i - cu) pu)^2 + dv^2 <= r^2 in double (cu in pixel-centre units, dv the row's offset in metres),
// the test the clumping index has always made pixel by pixel. It holds on one interval of i (it only grows with
// |i - cu|), found from the square root and then settled at both ends by the test itself, so the pixels are exactly
// those the test picks one by one; the row between them is shaded without a test, or a branch, per pixel.
struct PixelSpan {
  int first, last;  // empty when last < first
};

PixelSpan disc_row(double cu, double dv, double r, double pu) {
  auto covered = [&](int i) {
    const double du = (i - cu) * pu;
    return !(du * du + dv * dv > r * r);
  };
  const int lowest = static_cast<int>(std::ceil(cu - r / pu)), highest = static_cast<int>(std::floor(cu + r / pu));
  const double half = std::sqrt(std::max(0.0, r * r - dv * dv)) / pu;
  int first = std::clamp(static_cast<int>(std::ceil(cu - half)), lowest, highest + 1);
  int last = std::clamp(static_cast<int>(std::floor(cu + half)), lowest - 1, highest);
  while (first > lowest && covered(first - 1)) --first;
  while (first <= last && !covered(first)) ++first;
  while (last < highest && covered(last + 1)) ++last;
  while (last >= first && !covered(last)) --last;
  return {first, last};
}

// One more shadow on the pixels first .. last of a row, each capped at 255.
void shade_pixels(std::uint8_t* row, int first, int last) {
  for (int i = first; i <= last; ++i) row[i] = static_cast<std::uint8_t>(row[i] + (row[i] < 255 ? 1 : 0));
}

// A ball's disc on the face of its slab: centre (cu, cv) in pixel-centre units, radius r (m), and the rows
// first_row .. last_row it spans before wrapping.
struct FaceDisc {
  double cu, cv, r;
  int first_row, last_row;
};

// Where the face's pixel rows lie: wrapped into it on a periodic side, else -1 outside it.
struct FaceRows {
  int count;
  bool wraps;
  int at(int j) const { return wraps ? wrap_cell(j, count) : (j >= 0 && j < count ? j : -1); }
};

// The bands (rows of cells) a disc's rows fall in, each once. Its rows are consecutive, so the bands they meet are
// too: one band can come back only where the rows wrap around a periodic face to the band they began in, or cover
// it all.
template <typename Visit>
void for_each_band(const FaceDisc& disc, const FaceRows& rows, int P, Visit visit) {
  if (rows.wraps && disc.last_row - disc.first_row + 1 >= rows.count) {
    for (int band = 0; band < rows.count / P; ++band) visit(band);
    return;
  }
  int first_band = -1, previous = -1;
  for (int j = disc.first_row; j <= disc.last_row; ++j) {
    const int iv = rows.at(j);
    if (iv < 0) continue;
    const int band = iv / P;
    if (band == previous || band == first_band) continue;
    if (first_band < 0) first_band = band;
    previous = band;
    visit(band);
  }
}

// A slab's face in pixels: nu across (u), the rows (v), P pixels a cell each way, pixels pu x pv metres.
struct Face {
  int nu;
  bool wraps_u;
  FaceRows rows;
  int P;
  double pu, pv;
};

// The rows of a disc that fall in band b, shaded on the band's pixels (P rows of nu).
void shade_disc_in_band(const FaceDisc& disc, int b, const Face& face, std::uint8_t* band_pixels) {
  const int P = face.P, nu = face.nu;
  for (int j = disc.first_row; j <= disc.last_row; ++j) {
    const int iv = face.rows.at(j);
    if (iv < 0 || iv / P != b) continue;
    const PixelSpan span = disc_row(disc.cu, (j - disc.cv) * face.pv, disc.r, face.pu);
    std::uint8_t* row = band_pixels + std::size_t(iv - b * P) * nu;
    if (!face.wraps_u) {
      shade_pixels(row, std::max(span.first, 0), std::min(span.last, nu - 1));
      continue;
    }
    // a wrapping face: the span in pieces, each inside the row (a disc wider than the face shades a pixel once for
    // each time it covers it, as the pixel-by-pixel loop did)
    for (int piece = span.first; piece <= span.last;) {
      const int start = wrap_cell(piece, nu), length = std::min(span.last - piece + 1, nu - start);
      shade_pixels(row, start, start + length - 1);
      piece += length;
    }
  }
}

// Each cell a of a shaded band: the sum of t^n over its P x P pixels (kept[n] = t^n), row by row, and the number of
// shadows on them; cells without a shadow are left out.
template <typename AddCell>
void add_band_cells(const std::uint8_t* band_pixels, const Face& face, const std::vector<double>& kept,
                    AddCell add_cell) {
  const int P = face.P;
  for (int a = 0; a < face.nu / P; ++a) {
    double gap = 0, count = 0;
    for (int j = 0; j < P; ++j)
      for (int i = a * P; i < (a + 1) * P; ++i) {
        const int n = band_pixels[std::size_t(j) * face.nu + i];
        gap += kept[n];
        count += n;
      }
    if (count > 0) add_cell(a, gap, count);
  }
}

// Balls cast their shadow along `axis` onto the face of their own slab of cells; per cell of the slab, adds
// -ln(mean transmission) to `log_gap` and the mean number of shadows over a pixel to `hits`.
// Each slab's face is rasterised one band of cells at a time (P rows of pixels), its discs' rows that fall in the
// band, and the band's cells summed before the next: the pixels of a band stay in the nearer caches, where a whole
// face (7 MB at 10^6 balls) missed them at the first touch of nearly every row (docs/performance.md "The clumping
// index band by band, and the tiles' searches on the worker threads"). Every pixel gets the same shadows and every
// cell the same sum, in the same order, as when the face was rasterised whole.
void add_shadows_along(int axis, const OccluderSet& occluders, const VoxelGrid& grid, double t, int pixels_per_cell,
                       std::vector<double>& log_gap, std::vector<double>& hits) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int P = pixels_per_cell;
  const double pu = grid.cell[u] / P, pv = grid.cell[v] / P;
  const Face face{grid.dims[u] * P, grid.periodic && u < 2, {grid.dims[v] * P, grid.periodic && v < 2}, P, pu, pv};
  std::vector<std::vector<std::uint32_t>> slabs(grid.dims[axis]);
  for (std::size_t k = 0; k < occluders.ball_count; ++k)
    slabs[slab_of(occluders.centres[k][axis], grid.origin[axis], grid.cell[axis], grid.dims[axis],
                  grid.periodic && axis < 2)]
        .push_back(static_cast<std::uint32_t>(k));
  std::vector<double> kept(256);  // t^n
  for (int n = 0; n < 256; ++n) kept[n] = std::pow(t, n);
  // A slab writes only its own cells: blocks of slabs are rasterised on the worker threads, four blocks a thread,
  // and every cell gets the same sums as in one loop over the slabs in order.
  const std::size_t slab_count = std::size_t(grid.dims[axis]);
  const std::size_t blocks = std::min<std::size_t>(slab_count, 4 * std::size_t(worker_threads()));
  const std::size_t block = (slab_count + blocks - 1) / blocks;
  parallel_for_blocks(slab_count, block, [&](std::size_t first, std::size_t last) {
    std::vector<std::uint8_t> band_pixels(std::size_t(P) * face.nu);
    std::vector<FaceDisc> discs;
    std::vector<std::uint32_t> band_start(grid.dims[v] + 1), band_fill, band_discs;
    for (int s = int(first); s < int(last); ++s) {
      if (slabs[s].empty()) continue;
      discs.clear();
      for (const auto k : slabs[s]) {
        const double cu = (occluders.centres[k][u] - grid.origin[u]) / pu - 0.5;  // in pixel-centre units
        const double cv = (occluders.centres[k][v] - grid.origin[v]) / pv - 0.5;
        const double r = occluders.radii[k];
        discs.push_back(
            {cu, cv, r, static_cast<int>(std::ceil(cv - r / pv)), static_cast<int>(std::floor(cv + r / pv))});
      }
      // The discs of each band, in the slab's order (a counting sort; a disc across two bands is in both).
      std::fill(band_start.begin(), band_start.end(), 0);
      for (const FaceDisc& disc : discs) for_each_band(disc, face.rows, P, [&](int band) { ++band_start[band + 1]; });
      for (int b = 0; b < grid.dims[v]; ++b) band_start[b + 1] += band_start[b];
      band_discs.resize(band_start.back());
      band_fill.assign(band_start.begin(), band_start.end() - 1);
      for (std::uint32_t d = 0; d < discs.size(); ++d)
        for_each_band(discs[d], face.rows, P, [&](int band) { band_discs[band_fill[band]++] = d; });
      for (int b = 0; b < grid.dims[v]; ++b) {
        if (band_start[b] == band_start[b + 1]) continue;  // no shadow: every cell of the band keeps its density
        std::fill(band_pixels.begin(), band_pixels.end(), 0);
        for (auto e = band_start[b]; e < band_start[b + 1]; ++e)
          shade_disc_in_band(discs[band_discs[e]], b, face, band_pixels.data());
        add_band_cells(band_pixels.data(), face, kept, [&](int a, double gap, double count) {
          int at[3];
          at[axis] = s, at[u] = a, at[v] = b;
          const std::size_t cell = grid.index(at[0], at[1], at[2]);
          log_gap[cell] -= std::log(gap / (P * P));
          hits[cell] += count / (P * P);
        });
      }
    }
  });
}

}  // namespace

std::vector<double> cell_clumping_index(const OccluderSet& occluders, const VoxelGrid& grid, double t) {
  std::vector<double> omega(grid.cell_count(), 1.0);
  if (t >= 1.0 || occluders.ball_count == 0) return omega;
  double mean_radius = 0;
  for (std::size_t k = 0; k < occluders.ball_count; ++k) mean_radius += occluders.radii[k] / occluders.ball_count;
  if (mean_radius <= 0) return omega;
  // pixels of about a third of a ball radius, so a disc's rasterised area is within a few % of pi r^2; at most
  // 2^26 pixels on the largest face of the grid (the memory of a whole face once; now a band of it is held, but the
  // pixel size is part of the answer, so the rule stays)
  const double cell = std::min({grid.cell.x, grid.cell.y, grid.cell.z});
  const double largest_face =
      std::max({double(grid.dims.x) * grid.dims.y, double(grid.dims.y) * grid.dims.z, double(grid.dims.z) * grid.dims.x});
  const double fine = std::ceil(3.0 * cell / mean_radius);
  const double affordable = std::floor(std::sqrt(double(1 << 26) / largest_face));
  const int pixels_per_cell = static_cast<int>(std::clamp(std::min(fine, affordable), 4.0, 32.0));
  std::vector<double> log_gap(grid.cell_count(), 0.0), hits(grid.cell_count(), 0.0);
  for (int axis = 0; axis < 3; ++axis) add_shadows_along(axis, occluders, grid, t, pixels_per_cell, log_gap, hits);
  for (std::size_t c = 0; c < omega.size(); ++c)
    if (hits[c] > 0) omega[c] = log_gap[c] / ((1.0 - t) * hits[c]);
  return omega;
}

}  // namespace heliostand
