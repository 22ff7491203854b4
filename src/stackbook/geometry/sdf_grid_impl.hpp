#pragma once
// Implementation of the signed-distance grid declared in sdf_grid.hpp (\ref ch06).
// Instantiated for D = 2 and D = 3 in sdf_grid.cpp.

#include <algorithm>
#include <cmath>

namespace stackbook {

namespace detail {

/// Weight of corner `mask` of a cell at local coordinates t: the product over the axes of
/// t_k (bit k set) or 1 - t_k (bit k clear), Eq. (6.11).
template <int D>
double cornerWeight(unsigned mask, const Vec<D>& t) {
  double w = 1.0;
  for (int k = 0; k < D; ++k) w *= (mask >> k) & 1u ? t[k] : 1.0 - t[k];
  return w;
}

inline void requireSetting(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("SdfGridSettings: " + what);
}

}  // namespace detail

template <int D>
SdfGrid<D>::SdfGrid(const Vec<D>& origin, double cellSize, const Index& nodeCounts,
                    std::vector<double> values, SdfGradientMethod gradient)
    : origin_(origin), h_(cellSize), n_(nodeCounts), values_(std::move(values)),
      gradient_(gradient) {
  std::int64_t total = 1;
  for (int k = 0; k < D; ++k) {
    if (n_[k] < 2) {
      throw std::invalid_argument("SdfGrid: every axis needs at least 2 nodes");
    }
    strides_[k] = total;
    total *= n_[k];
  }
  if (static_cast<std::int64_t>(values_.size()) != total) {
    throw std::invalid_argument("SdfGrid: the number of values does not match the node counts");
  }
  if (!(h_ > 0.0) || !std::isfinite(h_)) {
    throw std::invalid_argument("SdfGrid: the cell size must be finite and positive");
  }
  Vec<D> upper;
  for (int k = 0; k < D; ++k) upper[k] = origin_[k] + h_ * (n_[k] - 1);
  box_ = Aabb<D>{origin_, upper};
  // [grid_lipschitz]
  // Inside a cell, d phi / d x_k is a weighted mean (weights >= 0, summing to 1) of the
  // differences (phi_hi - phi_lo) / h of the cell's edges along axis k (Eq. (6.11)), so
  // |d phi / d x_k| <= a_k, the largest such difference anywhere on the grid, and
  // |grad phi| <= sqrt(sum a_k^2) in every cell; phi is continuous, so that bounds it on the
  // whole box. Outside, phi(p(x)) + |x - p(x)| (Eq. (6.14)) adds at most 1 (the distance to a
  // box is 1-Lipschitz, and so is the nearest point p).
  double sum = 0.0;
  for (int k = 0; k < D; ++k) {
    double a = 0.0;
    for (std::int64_t i = 0; i < total; ++i) {
      if ((i / strides_[k]) % n_[k] == n_[k] - 1) continue;  // no node above along k
      a = std::max(a, std::abs(values_[static_cast<std::size_t>(i + strides_[k])] -
                               values_[static_cast<std::size_t>(i)]));
    }
    sum += (a / h_) * (a / h_);
  }
  lipschitz_ = std::sqrt(sum) + 1.0;
  if (!std::isfinite(lipschitz_)) lipschitz_ = 0.0;  // unknown: no candidate lists
  // [grid_lipschitz]
}

template <int D>
void SdfGrid<D>::locate(const Vec<D>& x, Index& cell, Vec<D>& t) const {
  for (int k = 0; k < D; ++k) {
    const std::size_t kk = static_cast<std::size_t>(k);
    const double s = (x[k] - origin_[k]) / h_;
    // For 0 <= s < 2^31 truncation is the floor (the only case a point of the grid box
    // gives); anything else, a NaN included, takes the floor and the clamp.
    const int c = s >= 0.0 && s < 2147483647.0 ? std::min(static_cast<int>(s), n_[kk] - 2)
                                               : std::clamp(static_cast<int>(std::floor(s)), 0, n_[kk] - 2);
    cell[kk] = c;
    t[k] = std::clamp(s - c, 0.0, 1.0);
  }
}

// [grid_interpolate]
template <int D>
double SdfGrid<D>::interpolate(const Vec<D>& x) const {
  static_assert(D == 2 || D == 3);
  // The cell and the local coordinates t as locate() finds them, and the corners' linear
  // indices as the cell's plus the axis strides: the same cell, the same t, the same
  // weights (cornerWeight()'s products, factor by factor) and the same sum in the same
  // corner order, so the same bits, written out for D = 2 and 3 so that no loop or branch
  // runs per corner. For s >= 0 (x in the grid box, the only case value() asks for)
  // truncation is the floor; any other s (a NaN) takes locate() itself.
  std::array<double, D> t;
  std::int64_t base = 0;
  const auto axis = [&](int k) {
    const std::size_t kk = static_cast<std::size_t>(k);
    const double s = (x[k] - origin_[k]) / h_;
    int c = 0;
    if (s >= 0.0 && s < 2147483647.0) {
      c = std::min(static_cast<int>(s), n_[kk] - 2);
    } else {
      Index cell;
      Vec<D> local;
      locate(x, cell, local);
      c = cell[kk];
    }
    t[kk] = std::clamp(s - c, 0.0, 1.0);
    base += strides_[kk] * c;
  };
  double phi = 0.0;
  if constexpr (D == 2) {  // the 2^D corners, Eq. (6.11); bit k of the corner is axis k
    axis(0);
    axis(1);
    const double* v = values_.data() + base;
    const std::int64_t s1 = strides_[1];
    const double t0 = t[0], t1 = t[1], u0 = 1.0 - t0, u1 = 1.0 - t1;
    phi += u0 * u1 * v[0];
    phi += t0 * u1 * v[1];
    phi += u0 * t1 * v[s1];
    phi += t0 * t1 * v[s1 + 1];
  } else if constexpr (D == 3) {
    axis(0);
    axis(1);
    axis(2);
    const double* v = values_.data() + base;
    const std::int64_t s1 = strides_[1], s2 = strides_[2];
    const double t0 = t[0], t1 = t[1], t2 = t[2], u0 = 1.0 - t0, u1 = 1.0 - t1, u2 = 1.0 - t2;
    phi += u0 * u1 * u2 * v[0];
    phi += t0 * u1 * u2 * v[1];
    phi += u0 * t1 * u2 * v[s1];
    phi += t0 * t1 * u2 * v[s1 + 1];
    phi += u0 * u1 * t2 * v[s2];
    phi += t0 * u1 * t2 * v[s2 + 1];
    phi += u0 * t1 * t2 * v[s2 + s1];
    phi += t0 * t1 * t2 * v[s2 + s1 + 1];
  }
  return phi;
}
// [grid_interpolate]

// [grid_value]
template <int D>
double SdfGrid<D>::value(const Vec<D>& x) const {
  if (box_.contains(x)) return interpolate(x);
  // Outside: phi(p) + |x - p| with p the nearest point of the grid box, Eq. (6.14).
  const Vec<D> p = x.cwiseMax(box_.lower).cwiseMin(box_.upper);
  return interpolate(p) + (x - p).norm();
}
// [grid_value]

template <int D>
Vec<D> SdfGrid<D>::nodeGradient(const Index& i) const {
  const std::int64_t base = linear(i);
  Vec<D> g;
  for (int k = 0; k < D; ++k) g[k] = nodeDifference(base, i[static_cast<std::size_t>(k)], k);
  return g;
}

/// Eq. (6.13), right, in the cell `cell` at local coordinates t: the node gradients by
/// central differences (one-sided at the grid's edge), interpolated like phi. Written out
/// corner by corner with the corners' linear indices as the cell's plus the axis strides,
/// so that no index is recomputed and no loop runs per corner; each weight is the product
/// cornerWeight() forms, factor by factor, each difference and quotient is nodeGradient()'s
/// (both take nodeDifference()),
/// and the sum runs in the same corner order from zero, so the result has the same bits as
/// the loop over the corners (the loop the other method still runs).
template <int D>
Vec<D> SdfGrid<D>::centralGradientInCell(const Index& cell, const Vec<D>& t) const {
  static_assert(D == 2 || D == 3);
  std::int64_t base = 0;
  for (int k = 0; k < D; ++k) base += strides_[static_cast<std::size_t>(k)] * cell[static_cast<std::size_t>(k)];
  Vec<D> g = Vec<D>::Zero();
  const double u0 = 1.0 - t[0], u1 = 1.0 - t[1];
  if constexpr (D == 2) {
    const std::int64_t s1 = strides_[1];
    const int c0 = cell[0], c1 = cell[1];
    const auto add = [&](double w, std::int64_t node, int a0, int a1) {
      g[0] += w * nodeDifference(node, a0, 0);
      g[1] += w * nodeDifference(node, a1, 1);
    };
    add(1.0 * u0 * u1, base, c0, c1);                   // corner 00
    add(1.0 * t[0] * u1, base + 1, c0 + 1, c1);         // corner 10 (bit 0 set)
    add(1.0 * u0 * t[1], base + s1, c0, c1 + 1);        // corner 01
    add(1.0 * t[0] * t[1], base + s1 + 1, c0 + 1, c1 + 1);
  } else {
    const std::int64_t s1 = strides_[1], s2 = strides_[2];
    const int c0 = cell[0], c1 = cell[1], c2 = cell[2];
    const double u2 = 1.0 - t[2];
    const auto add = [&](double w, std::int64_t node, int a0, int a1, int a2) {
      g[0] += w * nodeDifference(node, a0, 0);
      g[1] += w * nodeDifference(node, a1, 1);
      g[2] += w * nodeDifference(node, a2, 2);
    };
    add(1.0 * u0 * u1 * u2, base, c0, c1, c2);
    add(1.0 * t[0] * u1 * u2, base + 1, c0 + 1, c1, c2);
    add(1.0 * u0 * t[1] * u2, base + s1, c0, c1 + 1, c2);
    add(1.0 * t[0] * t[1] * u2, base + s1 + 1, c0 + 1, c1 + 1, c2);
    add(1.0 * u0 * u1 * t[2], base + s2, c0, c1, c2 + 1);
    add(1.0 * t[0] * u1 * t[2], base + s2 + 1, c0 + 1, c1, c2 + 1);
    add(1.0 * u0 * t[1] * t[2], base + s2 + s1, c0, c1 + 1, c2 + 1);
    add(1.0 * t[0] * t[1] * t[2], base + s2 + s1 + 1, c0 + 1, c1 + 1, c2 + 1);
  }
  return g;
}

// [grid_gradient]
template <int D>
Vec<D> SdfGrid<D>::gradientByCorners(const Vec<D>& x, SdfGradientMethod method) const {
  Index cell;
  Vec<D> t;
  locate(x, cell, t);
  Vec<D> g = Vec<D>::Zero();
  for (unsigned mask = 0; mask < (1u << D); ++mask) {
    Index corner = cell;
    for (int k = 0; k < D; ++k) corner[k] += (mask >> k) & 1u;
    if (method == SdfGradientMethod::CentralDifferences) {
      // Node gradients by central differences, interpolated like phi: Eq. (6.13), right.
      g += detail::cornerWeight<D>(mask, t) * nodeGradient(corner);
    } else {
      // d/dx_k of the interpolant: the weight's factor t_k or 1 - t_k becomes +-1/h.
      const double phi = nodeValue(corner);
      for (int k = 0; k < D; ++k) {
        double w = ((mask >> k) & 1u ? 1.0 : -1.0) / h_;  // Eq. (6.13), left
        for (int j = 0; j < D; ++j) {
          if (j != k) w *= (mask >> j) & 1u ? t[j] : 1.0 - t[j];
        }
        g[k] += w * phi;
      }
    }
  }
  return g;
}

template <int D>
Vec<D> SdfGrid<D>::gradientInside(const Vec<D>& x, SdfGradientMethod method) const {
  if (method != SdfGradientMethod::CentralDifferences) return gradientByCorners(x, method);
  // The corner loop above, written out (centralGradientInCell()): the same bits, faster.
  Index cell;
  Vec<D> t;
  locate(x, cell, t);
  return centralGradientInCell(cell, t);
}

template <int D>
Vec<D> SdfGrid<D>::gradient(const Vec<D>& x) const {
  if (box_.contains(x)) return gradientInside(x, gradient_);
  // Gradient of the extension phi(p(x)) + |x - p(x)|, Eq. (6.14): along a clamped axis
  // p does not move with x, so that component of grad phi(p) drops out and the unit
  // vector (x - p)/|x - p| takes its place.
  const Vec<D> p = x.cwiseMax(box_.lower).cwiseMin(box_.upper);
  Vec<D> g = gradientInside(p, gradient_);
  const Vec<D> away = x - p;
  for (int k = 0; k < D; ++k) {
    if (away[k] != 0.0) g[k] = 0.0;
  }
  return g + away / away.norm();
}

template <int D>
Vec<D> SdfGrid<D>::normal(const Vec<D>& x) const {
  constexpr double kVanishing = 1e-8;  // |grad phi| is 1 away from the medial axis
  const Vec<D> g = gradient(x);
  const double length = g.norm();
  if (length > kVanishing) return g / length;
  if (box_.contains(x)) {
    const SdfGradientMethod other = gradient_ == SdfGradientMethod::CentralDifferences
                                        ? SdfGradientMethod::InterpolantDerivative
                                        : SdfGradientMethod::CentralDifferences;
    const Vec<D> g2 = gradientInside(x, other);
    if (g2.norm() > kVanishing) return g2.normalized();
  }
  Vec<D> fallback = Vec<D>::Zero();
  fallback[D - 1] = 1.0;
  return fallback;
}
// [grid_gradient]

template <int D>
void sdfGridLayout(const Aabb<D>& region, const SdfGridSettings& settings, Vec<D>& origin,
                   double& cellSize, std::array<int, D>& nodeCounts) {
  detail::requireSetting(!region.isEmpty() && region.lower.allFinite() && region.upper.allFinite(),
                         "the region to cover is empty or not finite");
  detail::requireSetting(settings.paddingCells >= 1, "paddingCells must be at least 1, got " +
                                                         std::to_string(settings.paddingCells));
  detail::requireSetting(std::isfinite(settings.cellSize) && settings.cellSize >= 0.0,
                         "cellSize must be finite and >= 0 (0: use cellsAcrossLargestExtent)");
  const Vec<D> extent = region.extent();
  const double largest = extent.maxCoeff();
  if (settings.cellSize > 0.0) {
    cellSize = settings.cellSize;
  } else {
    detail::requireSetting(settings.cellsAcrossLargestExtent >= 2,
                           "cellsAcrossLargestExtent must be at least 2, got " +
                               std::to_string(settings.cellsAcrossLargestExtent));
    detail::requireSetting(largest > 0.0, "the region has zero extent");
    cellSize = largest / settings.cellsAcrossLargestExtent;
  }
  std::int64_t total = 1;
  for (int k = 0; k < D; ++k) {
    // Whole cells covering the extent (a hair of slack so that an exact multiple is not
    // rounded up by a last-bit error), plus the padding on both sides.
    const double cells = std::max(1.0, std::ceil(extent[k] / cellSize - 1e-9));
    detail::requireSetting(cells + 2.0 * settings.paddingCells < 1e8,
                           "the grid would have more than 1e8 cells along an axis");
    const int count = static_cast<int>(cells) + 2 * settings.paddingCells;
    nodeCounts[k] = count + 1;
    origin[k] = region.center()[k] - 0.5 * count * cellSize;
    total *= count + 1;
    detail::requireSetting(total <= settings.maxNodes,
                           "the grid would have more than maxNodes = " +
                               std::to_string(settings.maxNodes) + " nodes");
  }
}

// [build_sdf_grid]
template <int D>
SdfGrid<D> buildSdfGrid(const SurfaceMesh<D>& mesh, const SdfGridSettings& settings,
                        const std::string& source) {
  if (settings.validate) validateMesh<D>(mesh, source);
  detail::requireSetting(settings.bvhLeafSize >= 1, "bvhLeafSize must be at least 1");
  Vec<D> origin;
  double h = 0.0;
  std::array<int, D> n{};
  sdfGridLayout<D>(mesh.bounds(), settings, origin, h, n);
  std::int64_t total = 1;
  for (const int c : n) total *= c;
  const auto position = [&](std::int64_t index) {
    Vec<D> p;
    for (int k = 0; k < D; ++k) {
      const std::int64_t count = n[k];
      p[k] = origin[k] + h * static_cast<double>(index % count);
      index /= count;
    }
    return p;
  };
  // [grid_node_distances]
  // 1. Exact unsigned distance at every node (Eqs. (6.3)-(6.5)), nearest face first tried:
  //    the previous node's, which is close along the fastest axis.
  const FaceBvh<D> bvh(mesh, settings.bvhLeafSize);
  std::vector<double> distance(total);
  int hint = -1;
  for (std::int64_t i = 0; i < total; ++i) {
    const NearestFace<D> nearest = bvh.nearest(mesh, position(i), hint);
    distance[i] = nearest.distance();
    hint = nearest.face;
  }
  SdfBuildStats stats;  // [grid_node_distances]
  stats.nodes = total;
  stats.faceTests = bvh.faceTests();

  // 2. The sign (Eqs. (6.8)-(6.10)). A node within rounding of the surface (d <= 1e-12 h)
  //    keeps phi = +d, about 1e-17: there w is 1/2 and the sign means nothing.
  const double onSurface = 1e-12 * h;
  std::vector<char> inside(total, 0);
  const auto evaluate = [&](std::int64_t i) {
    const double w = windingNumber<D>(mesh, position(i));
    ++stats.windingEvaluations;
    stats.maxWindingDeviation = std::max(stats.maxWindingDeviation, std::abs(w - std::round(w)));
    return w > 0.5;  // Eq. (6.9)
  };
  if (settings.sign == SdfSignMethod::WindingNumberPerNode) {
    for (std::int64_t i = 0; i < total; ++i) {
      if (distance[i] > onSurface) inside[i] = evaluate(i);
    }
  } else {  // [grid_sign_regions]
    // Union-find over the links i -- i + e_k with d_i + d_j > h (Eq. (6.10)): the two balls
    // of radius d_i and d_j hold no surface point and together cover the segment between
    // the nodes, so the segment does not cross the surface and w is the same at both ends.
    // The margin 1e-9 h keeps rounding in d from joining nodes the surface separates.
    std::vector<std::int64_t> parent(total);
    std::iota(parent.begin(), parent.end(), std::int64_t{0});
    const auto find = [&](std::int64_t i) {
      while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
      }
      return i;
    };
    const double joinThreshold = h * (1.0 + 1e-9);
    std::int64_t stride = 1;
    for (int k = 0; k < D; ++k) {
      const std::int64_t count = n[k];
      for (std::int64_t i = 0; i < total; ++i) {
        if ((i / stride) % count == count - 1) continue;  // last node along axis k
        const std::int64_t j = i + stride;
        if (distance[i] + distance[j] <= joinThreshold) continue;
        const std::int64_t ri = find(i), rj = find(j);
        if (ri != rj) parent[std::max(ri, rj)] = std::min(ri, rj);
      }
      stride *= count;
    }
    // Each region's winding number is taken at its node farthest from the surface, where
    // the sum is best conditioned.
    std::vector<std::int64_t> representative(total, -1);
    for (std::int64_t i = 0; i < total; ++i) {
      const std::int64_t r = find(i);
      std::int64_t& rep = representative[r];
      if (rep < 0 || distance[i] > distance[rep]) rep = i;
    }
    std::vector<char> regionInside(total, 0);
    for (std::int64_t r = 0; r < total; ++r) {
      const std::int64_t rep = representative[r];
      if (rep < 0) continue;  // not a root
      ++stats.signRegions;
      if (distance[rep] > onSurface) regionInside[r] = evaluate(rep);
    }
    for (std::int64_t i = 0; i < total; ++i) inside[i] = regionInside[find(i)];
  }  // [grid_sign_regions]

  std::vector<double> values(total);
  for (std::int64_t i = 0; i < total; ++i) {
    const double d = distance[i];
    values[i] = inside[i] ? -d : d;  // Eq. (6.1)
  }
  SdfGrid<D> grid(origin, h, n, std::move(values), settings.gradient);
  grid.setStats(stats);
  return grid;
}
// [build_sdf_grid]

template <int D>
SdfGrid<D> sampleSdfGrid(const std::function<double(const Vec<D>&)>& phi, const Aabb<D>& region,
                         const SdfGridSettings& settings) {
  Vec<D> origin;
  double h = 0.0;
  std::array<int, D> n{};
  sdfGridLayout<D>(region, settings, origin, h, n);
  std::int64_t total = 1;
  for (const int c : n) total *= c;
  std::vector<double> values(total);
  for (std::int64_t i = 0; i < total; ++i) {
    std::int64_t rest = i;
    Vec<D> p;
    for (int k = 0; k < D; ++k) {
      const std::int64_t count = n[k];
      p[k] = origin[k] + h * static_cast<double>(rest % count);
      rest /= count;
    }
    values[i] = phi(p);
  }
  SdfGrid<D> grid(origin, h, n, std::move(values), settings.gradient);
  SdfBuildStats stats;
  stats.nodes = total;
  grid.setStats(stats);
  return grid;
}

}  // namespace stackbook
