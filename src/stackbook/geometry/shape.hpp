#pragma once
/// \file
/// \brief The two representations GBF keeps for every body: surface samples (the points
/// tested for interference) and a signed distance function (inside/outside and normals).
/// Both live in the body frame (origin at the centre of mass, principal axes).
/// Chapter 6 implements it (analytic primitives, signed-distance grids); chapter 7 uses it.

#include <string>
#include <vector>

#include "stackbook/geometry/aabb.hpp"
#include "stackbook/geometry/sample_chunks.hpp"

namespace stackbook {

// [shape_interface]
template <int D>
class Shape {
 public:
  virtual ~Shape() = default;

  /// Signed distance phi(x) at a body-frame point: negative inside, positive outside,
  /// |phi| the distance to the surface (exact or interpolated; see the implementation).
  virtual double signedDistance(const Vec<D>& x) const = 0;

  /// Unit outward normal N = grad(phi)/|grad(phi)| at a body-frame point. Defined
  /// everywhere, also outside the region a grid covers (chapter 6 documents how).
  virtual Vec<D> normal(const Vec<D>& x) const = 0;

  /// Body-frame points on the surface that are tested against other bodies' phi
  /// (the mesh vertices, possibly refined).
  virtual const std::vector<Vec<D>>& surfaceSamples() const = 0;

  /// Body-frame bounding box of the shape.
  virtual Aabb<D> bounds() const = 0;

  /// A short description for messages and summaries ("box 1 x 1 x 1", "mesh ring.obj").
  virtual std::string describe() const = 0;

  /// The exact deepest-point query (chapter 11): the body-frame point of this surface
  /// deepest inside `other`, whose body frame this one maps into by x -> M x + t. Only shapes
  /// that know their surface exactly answer (the convex analytic primitives); the others
  /// return false and leave `point` alone.
  virtual bool deepestPoint(const Shape<D>& /*other*/, const Mat<D>& /*M*/, const Vec<D>& /*t*/,
                            Vec<D>& /*point*/) const {
    return false;
  }

  /// True when the deepest point is this shape's whole contact with a body (a strictly
  /// convex shape: sphere, disk), so that it may replace the surface samples.
  virtual bool deepestPointIsWholeContact() const { return false; }

  /// True when part of this shape's surface is curved (sphere, disk, capsule, a cylinder's side
  /// in 3D), where fixed samples make it a polygon: SurfaceQuery::RoundShapes asks the exact
  /// deepest point of these shapes only (chapter 12).
  virtual bool roundSurface() const { return false; }

  /// Boxes around runs of consecutive surface samples (chapter 7, "Skipping far samples"),
  /// built with the shape; null for a shape without them, whose samples the narrow phase
  /// then transforms one by one.
  virtual const SampleChunks<D>* sampleChunks() const { return nullptr; }

  /// A Lipschitz bound L of signedDistance(): |phi(x) - phi(y)| <= L |x - y| for all x, y
  /// (chapter 7, "Candidate lists"). 1 for an exact signed distance, a bound computed from the
  /// node values for a grid; 0, the default, when no bound is known, and then the narrow phase
  /// keeps no candidate lists against this shape.
  virtual double distanceLipschitz() const { return 0.0; }
};
// [shape_interface]

}  // namespace stackbook
