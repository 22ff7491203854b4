#pragma once
// Shapes for chapter 7's tests, built from chapter 6's analytic and grid shapes and
// chapter 5's meshes, in D = 2 and D = 3 from the same code; plus the convex hulls of the
// ring and the cup, which exist only here, to show what a convex approximation reports.

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

namespace stackbook::testing {

/// The boundary of a box with half extents h, every edge cut into `subdivisions` pieces.
template <int D>
SurfaceMesh<D> boxBoundary(const Vec<D>& halfExtents, int subdivisions = 1) {
  if constexpr (D == 2) {
    return rectanglePolygon(Vec2(2.0 * halfExtents), subdivisions);
  } else {
    return boxMesh(Vec3(2.0 * halfExtents), subdivisions);
  }
}

/// A box with exact phi whose surface samples are the vertices of its mesh: the corners
/// only for subdivisions = 1, a lattice on every face (and edge) for more.
template <int D>
BoxShape<D> boxShape(const Vec<D>& halfExtents, int subdivisions = 1) {
  return BoxShape<D>(BoxSdf<D>(halfExtents), boxBoundary<D>(halfExtents, subdivisions));
}

/// A disk (regular polygon of `resolution` vertices) or a ball (icosphere of level
/// `resolution`) with exact phi.
template <int D>
SphereShape<D> ballShape(double radius, int resolution) {
  if constexpr (D == 2) {
    return SphereShape<2>(SphereSdf<2>(radius), regularPolygon(radius, resolution));
  } else {
    return SphereShape<3>(SphereSdf<3>(radius), icosphereMesh(radius, resolution));
  }
}

/// A ring (annulus in 2D, torus in 3D) with exact phi; `segments` vertices around the
/// axis, `segments` / 2 around the tube (3D).
template <int D>
TorusShape<D> ringShape(double majorRadius, double minorRadius, int segments) {
  return TorusShape<D>(TorusSdf<D>(majorRadius, minorRadius),
                       ringBoundary<D>(majorRadius, minorRadius, segments, segments / 2));
}

/// The convex hull of the ring: the disk of radius R + r (2D); the points within r of the
/// flat disk of radius R (3D). phi = |(max(rho - R, 0), z)| - r, exact.
template <int D>
struct RingHullSdf {
  double majorRadius = 1.0;
  double minorRadius = 0.2;
  double distance(const Vec<D>& x) const {
    const double rho = x.template head<2>().norm();
    if constexpr (D == 2) {
      return rho - (majorRadius + minorRadius);
    } else {
      return Vec2(std::max(rho - majorRadius, 0.0), x[2]).norm() - minorRadius;
    }
  }
  Vec<D> normal(const Vec<D>& x) const {  // not needed by the tests: the outward radial
    return x.norm() > 0.0 ? Vec<D>(x.normalized()) : Vec<D>(Vec<D>::Unit(D - 1));
  }
  Aabb<D> bounds() const {
    Vec<D> h = Vec<D>::Constant(majorRadius + minorRadius);
    if constexpr (D == 3) h[2] = minorRadius;
    return Aabb<D>{Vec<D>(-h), h};
  }
};

/// A convex hull as a Shape: phi, N and bounds of the hull `Sdf`, surface samples of the
/// nonconvex body it wraps (they lie on or inside the hull, not necessarily on it).
template <int D, class Sdf>
class HullShape final : public Shape<D> {
 public:
  HullShape(Sdf sdf, std::vector<Vec<D>> samples)
      : sdf_(std::move(sdf)), samples_(std::move(samples)) {}
  double signedDistance(const Vec<D>& x) const override { return sdf_.distance(x); }
  Vec<D> normal(const Vec<D>& x) const override { return sdf_.normal(x); }
  const std::vector<Vec<D>>& surfaceSamples() const override { return samples_; }
  Aabb<D> bounds() const override { return sdf_.bounds(); }
  std::string describe() const override { return "convex hull"; }

 private:
  Sdf sdf_;
  std::vector<Vec<D>> samples_;
};

/// An Sdf moved by `offset` in the body frame, with its mesh's vertices as samples: a body
/// whose centre of mass (the body origin) is not the centre of its bounding box.
template <int D, class Sdf>
class OffsetShape final : public Shape<D> {
 public:
  OffsetShape(Sdf sdf, const SurfaceMesh<D>& mesh, const Vec<D>& offset)
      : sdf_(std::move(sdf)), offset_(offset) {
    for (const Vec<D>& v : mesh.vertices) samples_.push_back(v + offset);
  }
  double signedDistance(const Vec<D>& x) const override { return sdf_.distance(x - offset_); }
  Vec<D> normal(const Vec<D>& x) const override { return sdf_.normal(x - offset_); }
  const std::vector<Vec<D>>& surfaceSamples() const override { return samples_; }
  Aabb<D> bounds() const override {
    const Aabb<D> b = sdf_.bounds();
    return Aabb<D>{Vec<D>(b.lower + offset_), Vec<D>(b.upper + offset_)};
  }
  std::string describe() const override { return "offset " + sdf_.describe(); }

 private:
  Sdf sdf_;
  Vec<D> offset_;
  std::vector<Vec<D>> samples_;
};

}  // namespace stackbook::testing
