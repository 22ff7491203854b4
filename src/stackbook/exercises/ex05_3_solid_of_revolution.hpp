#pragma once
/// \file
/// \brief Exercise 5.3: a solid of revolution as a closed mesh, checked with Pappus's
/// theorem (chapter 5, "Exercises").

#include <vector>

#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook::exercises {

/// The closed, outward-oriented triangle mesh of the solid swept by a profile polygon turning
/// about the z axis. The profile is a counterclockwise loop of points (r, z) in the half-plane
/// r > 0 (it must not touch the axis). Each profile point k becomes the ring
/// (r cos u_i, r sin u_i, z) with u_i = 2 pi i / segments, i = 0..segments-1, stored as vertex
/// i * profile.size() + k; each profile edge and angular step gives one quad, split into two
/// triangles. A regular polygon of radius rho centred at (R, 0) gives torusMesh(R, rho, ...).
/// Throws std::invalid_argument for fewer than 3 profile points or segments, a point with
/// r <= 0 or non-finite, or a clockwise profile.
TriangleMesh revolveProfile(const std::vector<Vec2>& profile, int segments);

}  // namespace stackbook::exercises
