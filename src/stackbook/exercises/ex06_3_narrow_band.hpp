#pragma once
/// \file
/// \brief Exercise 6.3: a narrow-band signed-distance grid that stores node values only in
/// blocks near the surface, and what it saves (\ref ch06).

#include <cstdint>
#include <memory>

#include "stackbook/geometry/sdf_grid.hpp"

namespace stackbook::exercises {

/// The grid of clamp(phi, -w, w) for a band half-width w, stored sparsely: the nodes of
/// the dense grid are grouped in blocks of blockSize^D nodes; a block that has a node with
/// |phi| <= w keeps all its node values, every other block keeps only its sign (all its
/// nodes have |phi| > w and, as w >= sqrt(D) h, one sign).
///
/// value(x) is exactly the multilinear interpolation (Eq. (6.11)) of the clamped node
/// values clamp(phi_i, -w, w), so it equals the dense grid wherever every corner of x's
/// cell is within the band, keeps the sign everywhere, and outside the grid box follows
/// Eq. (6.14) like SdfGrid.
template <int D>
class NarrowBandGrid {
 public:
  /// Throws std::invalid_argument unless bandWidth >= sqrt(D) h (so that every cell the
  /// surface cuts has all its corners in the band) and blockSize >= 2.
  NarrowBandGrid(const SdfGrid<D>& dense, double bandWidth, int blockSize = 8);
  /// Interpolated clamp(phi, -w, w) at x.
  double value(const Vec<D>& x) const;
  /// Number of node values kept (whole kept blocks).
  std::int64_t storedNodes() const;
  /// Bytes of everything the grid stores: kept values plus the per-block table.
  std::size_t memoryBytes() const;

 private:
  struct Data;                        ///< your layout (defined in the .cpp)
  std::shared_ptr<const Data> data_;
};

}  // namespace stackbook::exercises
