#pragma once
/// \file
/// \brief Exercise 6.1: the exact signed distance of a rounded box, usable as the `Sdf` of
/// an AnalyticShape (\ref ch06).

#include <sstream>
#include <string>

#include "stackbook/geometry/aabb.hpp"

namespace stackbook::exercises {

/// A box with half extents h whose edges and corners are rounded with radius rho: the
/// points within rho of the inner box with half extents h - rho. rho = 0 is the box,
/// rho = h_k in every axis (a cube) the ball.
template <int D>
struct RoundedBoxSdf {
  Vec<D> halfExtents = Vec<D>::Constant(0.5);
  double radius = 0.1;

  /// Throws std::invalid_argument (naming the argument) unless every half extent is finite
  /// and positive and 0 <= radius <= the smallest half extent.
  RoundedBoxSdf(const Vec<D>& halfExtents, double radius);
  /// Exact signed distance: negative inside, |phi| the distance to the rounded surface.
  double distance(const Vec<D>& x) const;
  /// Unit outward normal, the gradient of distance(); on the medial axis (where it has
  /// no gradient) the same choice as BoxSdf::normal.
  Vec<D> normal(const Vec<D>& x) const;

  Aabb<D> bounds() const { return Aabb<D>{Vec<D>(-halfExtents), halfExtents}; }
  std::string describe() const {
    std::ostringstream out;
    out << "rounded box, radius " << radius;
    return out.str();
  }
};

}  // namespace stackbook::exercises
