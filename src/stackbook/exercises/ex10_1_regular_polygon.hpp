#pragma once
/// \file
/// \brief Exercise 10.1: a new shape for scene files, the 2D regular polygon: its outline
/// (what the outputs draw), its signed distance (what collision queries) and its mass
/// properties (what the step integrates), from a JSON shape description (\ref ch10).

#include <memory>

#include <nlohmann/json.hpp>

#include "stackbook/geometry/shape.hpp"
#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook {

/// Everything the scene loader needs from one shape description, in the body frame
/// (centroid at the origin): the same three things buildShape() in scene_shapes.cpp makes for
/// every built-in shape.
struct PolygonShapeBuild {
  /// The signed distance: negative inside, positive outside (a chapter 6 grid shape).
  std::shared_ptr<const Shape<2>> shape;
  /// The outline, counterclockwise, as SurfaceMesh<2> segments (the BodyVisual mesh), each
  /// side split into 4 equal segments: its vertices are the body's surface samples.
  Polygon outline;
  /// Area A in m^2 (a body of density rho has mass rho A).
  double area = 0.0;
  /// Polar moment of inertia about the centroid for unit density, in m^4 (a body of
  /// mass m has I = m unitMoment / area).
  double unitMoment = 0.0;
};

/// Builds the regular polygon described by `spec`:
///
///     {"type": "polygon", "sides": 6, "radius": 0.5, "sdfResolution": 64}
///
/// `sides` n is an integer in [3, 1000]; `radius` R > 0 (finite) is the circumradius, the
/// distance from the centre to each corner; `sdfResolution` (optional, integer in
/// [4, 1024], default 32) is the grid's cells across the largest extent. Corner k sits at
/// angle pi/2 + 2 pi k / n, so a corner points up. Throws std::invalid_argument whose
/// message names the offending field ("sides", "radius", "sdfResolution", "type", or an
/// unknown key) for any other input.
PolygonShapeBuild regularPolygonShape(const nlohmann::json& spec);

}  // namespace stackbook
