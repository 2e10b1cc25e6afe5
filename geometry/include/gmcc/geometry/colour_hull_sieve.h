#pragma once
/// \file colour_hull_sieve.h
/// A sieve for the vertices of an image's colour hull, one colour at a time: a few colours extreme
/// along 26 directions span a polytope Q inside the hull, and a colour strictly inside Q is no
/// vertex of the hull (Akl & Toussaint 1978's discarding of interior points, in 3-D; docs/math.md
/// §1b "The prepared route"). colour_hull_vertex_indices filters with it; a photograph's pixels
/// stream through it (photo/image_hull_sets.h) so that only the colours it keeps are gathered,
/// sorted and handed to the exact hull.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gmcc {

/// For each of the 13 directions v in {−1, 0, 1}^3 \ {0} whose first non-zero component is
/// positive, the first colour (in the order added) of largest and of smallest v·c. Complexity
/// O(1) a colour.
class ExtremeColours {
 public:
  ExtremeColours();
  /// Offers colour `c` under the caller's `index` (channels exact doubles; the products
  /// v·c are exact for the integers below 2^16 of a pixel, and otherwise may round: any colour
  /// chosen is still one of the set, which is all the sieve needs).
  void add(std::size_t index, const std::array<double, 3>& c) {
    for (std::size_t j = 0; j < directions; ++j) {
      const double p = v_[j][0] * c[0] + v_[j][1] * c[1] + v_[j][2] * c[2];
      if (p > top_[j]) top_[j] = p, hi_[j] = index;
      if (p < bottom_[j]) bottom_[j] = p, lo_[j] = index;
    }
    any_ = true;
  }
  /// The indices of the colours chosen, increasing, without repeats; empty before any add.
  std::vector<std::size_t> indices() const;

 private:
  static constexpr std::size_t directions = 13;
  std::array<std::array<double, 3>, directions> v_;
  std::array<double, directions> top_, bottom_;
  std::array<std::size_t, directions> hi_{}, lo_{};
  bool any_ = false;  // a colour was added
};

/// Q = conv(corners) as planes n·x <= n·a through its triangles, for corners whose channels are
/// integers in [0, 2^16) (pixel values): n's coordinates are below 2^33 and n·a below 2^51 in
/// magnitude, all exact in double, so the test is exact (no filter). When the corners span fewer
/// than 3 dimensions Q has no interior and the sieve keeps every colour. A grid of at most 16^3
/// cells over Q's bounding box, each a power of 2 wide (a colour's cell is a shift of integers),
/// sorts Q's planes per cell by the closed cell's corners (integers below 2^18: every product below
/// 2^51, the sums below 2^53, still exact): a plane the whole cell satisfies strictly is left out,
/// a plane no point of the cell satisfies strictly marks the cell as outside Q, and the cell keeps
/// the planes that cross it (a linear function takes its extremes over a box at corners). A colour
/// is then tested against its cell's planes only: none in a cell inside Q.
class ColourHullSieve {
 public:
  /// The sieve of conv(corners). \throws std::invalid_argument if a channel is not an integer in
  /// [0, 2^16). Complexity: the exact hull of the corners (CGAL's Epick, exact on doubles), and
  /// 16^3 cells against its planes.
  explicit ColourHullSieve(const std::vector<std::array<double, 3>>& corners);
  /// Whether `c` (channels integers in [0, 2^16), unchecked) is strictly inside Q, exactly: then
  /// it is no vertex of the hull of any set holding the corners. O(the planes crossing its cell):
  /// O(1) in a cell inside or outside Q.
  bool strictly_inside(const std::array<double, 3>& c) const {
    if (planes_.empty()) return false;
    std::size_t cell = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      if (!(c[k] >= low_[k] && c[k] <= high_[k])) return false;  // outside the corners' box
      cell = cell * grid + ((static_cast<std::uint32_t>(c[k]) - static_cast<std::uint32_t>(low_[k])) >> shift_[k]);
    }
    if (outside_cell_[cell]) return false;
    for (std::uint32_t j = cell_first_[cell]; j < cell_first_[cell + 1]; ++j) {
      const Planes& f = cell_planes_[j];  // four planes at a time (vector instructions where there are)
      const Four r = {c[0], c[0], c[0], c[0]}, g = {c[1], c[1], c[1], c[1]}, b = {c[2], c[2], c[2], c[2]};
      const auto inside = f[0] * r + f[1] * g + f[2] * b < f[3];  // each lane 0 or −1
      if (!(inside[0] & inside[1] & inside[2] & inside[3])) return false;
    }
    return true;
  }
  /// How many planes bound Q (0 when it is flat).
  std::size_t facets() const { return planes_.size(); }

 private:
  static constexpr std::size_t grid = 16;
  void sort_planes_into_cells(const std::array<double, 3>& step);
  std::vector<std::array<double, 4>> planes_;
  std::array<double, 3> low_{}, high_{};  // the corners' box
  std::array<unsigned, 3> shift_{};       // cell i along k: [low + i·2^shift, low + (i + 1)·2^shift)
  // Per cell of the grid (grid^3, row-major in (r, g, b)): whether no colour of it is strictly
  // inside Q, and else the planes it must be tested against, four at a time in
  // cell_planes_[cell_first_[cell] .. cell_first_[cell + 1]).
  // Four planes n·x < d by coordinate; a plane n = 0, d = 1 (which every colour satisfies) fills
  // a cell's last four.
  typedef double Four __attribute__((vector_size(32)));
  using Planes = std::array<Four, 4>;  // n's three coordinates, then d
  std::vector<std::uint8_t> outside_cell_;
  std::vector<std::uint32_t> cell_first_;
  std::vector<Planes> cell_planes_;
};

}  // namespace gmcc
