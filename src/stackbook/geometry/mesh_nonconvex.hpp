#pragma once
/// \file
/// \brief Procedural nonconvex closed boundaries, the shapes GBF was built for (\ref ch06):
/// an L (union of lattice cells), a cup (open-top, with wall and bottom thickness, closed
/// as a solid), a bone (two balls joined by a neck, one manifold mesh), a capsule, a ring
/// (torus in 3D, annulus in 2D) and a star polygon.
///
/// The generators are dimension-generic where the shape has a natural 2D counterpart:
/// - `latticeSolidBoundary<D>` unions unit squares (2D) or cubes (3D);
/// - `revolvedBoundary<D>` turns a profile in the (r, z) half-plane into a solid of
///   revolution about the z axis (3D), or into the profile and its mirror image (2D: the
///   cross-section through the axis), so cupBoundary<2> is the U shape and
///   boneBoundary<2> the dumbbell outline.
/// Every mesh is closed and outward-oriented (surface_mesh.hpp), centred on the centre of
/// its bounding box (not on its centre of mass: chapter 5's moveToPrincipalFrame does
/// that), and passes validateMesh. Vertices lie exactly on the intended surface, so they
/// can serve as GBF's surface samples. Bad arguments throw std::invalid_argument naming the
/// function and the argument.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "stackbook/geometry/mesh_primitives.hpp"

namespace stackbook {

namespace detail {

inline void requireNonconvex(bool condition, const char* function, const std::string& what) {
  if (!condition) throw std::invalid_argument(std::string(function) + ": " + what);
}

/// Translate the mesh so that the centre of its bounding box is the origin.
template <int D>
void centreOnBounds(SurfaceMesh<D>& mesh) {
  const Vec<D> centre = mesh.bounds().center();
  for (Vec<D>& v : mesh.vertices) v -= centre;
}

/// The polyline through `points` with every segment split into pieces no longer than
/// maxSpacing (the points themselves are kept).
inline std::vector<Vec2> refinePolyline(const std::vector<Vec2>& points, double maxSpacing) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec2 a = points[i], b = points[i + 1];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / maxSpacing)));
    for (int s = 0; s < pieces; ++s) out.push_back(a + (b - a) * (double(s) / pieces));
  }
  out.push_back(points.back());
  return out;
}

}  // namespace detail

// [lattice_solid]
/// The boundary of a union of lattice cells of side cellSize: squares (2D) or cubes (3D),
/// cell (i, j[, k]) covering [i, i+1] x [j, j+1] (x [k, k+1]) times cellSize. Each cell face
/// between a filled and an empty cell becomes boundary, split into `subdivisions` pieces
/// per cell edge (segments in 2D, 2 triangles per square in 3D), with vertices shared
/// along the fine lattice. Cells that touch only at a corner or (3D) along an edge make a
/// non-manifold boundary, which validateMesh reports.
template <int D>
SurfaceMesh<D> latticeSolidBoundary(const std::vector<std::array<int, D>>& cells,
                                    double cellSize, int subdivisions = 1) {
  detail::requirePositiveLength("latticeSolidBoundary", "cellSize", cellSize);
  detail::requireCountAtLeast("latticeSolidBoundary", "subdivisions", subdivisions, 1);
  detail::requireNonconvex(!cells.empty(), "latticeSolidBoundary", "no cells given");
  const std::map<std::array<int, D>, int> filled = [&] {
    std::map<std::array<int, D>, int> m;
    for (const auto& c : cells) m.emplace(c, 1);
    return m;
  }();
  const int s = subdivisions;
  SurfaceMesh<D> mesh;
  std::map<std::array<int, D>, int> vertexOf;  // fine-lattice point -> vertex index
  const auto vertex = [&](const std::array<int, D>& p) {
    const auto found = vertexOf.find(p);
    if (found != vertexOf.end()) return found->second;
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = cellSize * p[k] / s;
    const int id = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(x);
    vertexOf.emplace(p, id);
    return id;
  };
  for (const auto& [cell, unused] : filled) {
    (void)unused;
    for (int a = 0; a < D; ++a) {
      for (int side = -1; side <= 1; side += 2) {
        std::array<int, D> neighbour = cell;
        neighbour[a] += side;
        if (filled.count(neighbour)) continue;
        // Fine-lattice coordinates of the face's corner with the smallest coordinates.
        std::array<int, D> base{};
        for (std::size_t k = 0; k < D; ++k) base[k] = cell[k] * s;
        base[a] += side > 0 ? s : 0;
        if constexpr (D == 2) {
          // Outward normal side*e_a; the body is on the left of a counterclockwise
          // boundary, so the segment runs along side * rot90(e_a): +e_1 for a = 0,
          // -e_0 for a = 1.
          const int u = 1 - a;
          const int direction = side * (a == 0 ? 1 : -1);
          for (int piece = 0; piece < s; ++piece) {
            std::array<int, 2> p = base, q = base;
            p[u] += piece;
            q[u] += piece + 1;
            if (direction > 0) {
              mesh.faces.push_back({vertex(p), vertex(q)});
            } else {
              mesh.faces.push_back({vertex(q), vertex(p)});
            }
          }
        } else {
          // With u = a+1, v = a+2 (mod 3), e_u x e_v = e_a: the quad (u, v) -> (u+1, v)
          // -> (u+1, v+1) -> (u, v+1) is counterclockwise seen from +e_a.
          const int u = (a + 1) % 3, v = (a + 2) % 3;
          for (int p = 0; p < s; ++p) {
            for (int q = 0; q < s; ++q) {
              const auto corner = [&](int dp, int dq) {
                std::array<int, 3> c = base;
                c[u] += p + dp;
                c[v] += q + dq;
                return vertex(c);
              };
              const int c00 = corner(0, 0), c10 = corner(1, 0), c11 = corner(1, 1),
                        c01 = corner(0, 1);
              if (side > 0) {
                detail::appendQuad(mesh, c00, c10, c11, c01);
              } else {
                detail::appendQuad(mesh, c00, c01, c11, c10);
              }
            }
          }
        }
      }
    }
  }
  detail::centreOnBounds<D>(mesh);
  return mesh;
}
// [lattice_solid]

/// The L: three lattice cells of side cellSize, (0,0), (1,0) and (0,1) (and one cell
/// deep in 3D: the L-block). Area 3 a^2, volume 3 a^3 for a = cellSize.
template <int D>
SurfaceMesh<D> lShapeBoundary(double cellSize = 0.5, int subdivisions = 2) {
  std::vector<std::array<int, D>> cells(3);
  cells[1][0] = 1;  // (1, 0[, 0])
  cells[2][1] = 1;  // (0, 1[, 0])
  return latticeSolidBoundary<D>(cells, cellSize, subdivisions);
}

// [revolved_boundary]
/// A solid of revolution about the z axis (3D), or its cross-section through the axis
/// (2D). `profile` is a polyline in the (r, z) half-plane from a point on the axis (r = 0)
/// to another point on the axis, with r > 0 in between, running counterclockwise around
/// the profile region (the solid on its left: up the outside, down the inside).
/// 3D: every interior profile point becomes a ring of `segments` vertices at angles
/// 2 pi k / segments, the two axis points become poles; the quad between neighbouring rings
/// is planar (an isosceles trapezoid), split into two triangles. 2D: the profile followed
/// by its mirror image r -> -r, as one counterclockwise loop.
template <int D>
SurfaceMesh<D> revolvedBoundary(const std::vector<Vec2>& profile, int segments = 48) {
  const char* fn = "revolvedBoundary";
  detail::requireCountAtLeast(fn, "number of profile points", static_cast<int>(profile.size()), 3);
  detail::requireCountAtLeast(fn, "segments", segments, 3);
  detail::requireNonconvex(profile.front().x() == 0.0 && profile.back().x() == 0.0, fn,
                           "the profile must start and end on the axis (r = 0)");
  for (std::size_t i = 1; i + 1 < profile.size(); ++i) {
    if (!(profile[i].x() > 0.0) || !profile[i].allFinite()) {
      std::ostringstream msg;
      msg << "profile point " << i << " (" << profile[i].transpose()
          << ") must have finite r > 0";
      detail::requireNonconvex(false, fn, msg.str());
    }
  }
  const int m = static_cast<int>(profile.size());
  SurfaceMesh<D> mesh;
  if constexpr (D == 2) {
    std::vector<Vec2> loop(profile.begin(), profile.end());
    for (int i = m - 2; i >= 1; --i) {
      const Vec2& p = profile[i];
      loop.push_back(Vec2(-p.x(), p.y()));
    }
    mesh = polygonFromLoop(loop);
  } else {
    // Vertex 0: bottom pole; ring i (profile point i, 1 <= i <= m-2) at 1 + (i-1) segments;
    // last vertex: top pole.
    mesh.vertices.push_back(Vec3(0.0, 0.0, profile.front().y()));
    for (int i = 1; i <= m - 2; ++i) {
      const Vec2& p = profile[i];
      for (int k = 0; k < segments; ++k) {
        const double angle = 2.0 * M_PI * k / segments;
        mesh.vertices.push_back(Vec3(p.x() * std::cos(angle), p.x() * std::sin(angle), p.y()));
      }
    }
    const int top = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(Vec3(0.0, 0.0, profile.back().y()));
    const auto ring = [&](int i, int k) { return 1 + (i - 1) * segments + (k % segments); };
    // Outward normal = d/d(angle) x d/d(profile) when the solid is on the profile's left,
    // so each quad runs first around the axis, then along the profile.
    for (int k = 0; k < segments; ++k) {
      mesh.faces.push_back({0, ring(1, k + 1), ring(1, k)});  // bottom fan
      for (int i = 1; i + 1 <= m - 2; ++i) {
        detail::appendQuad(mesh, ring(i, k), ring(i, k + 1), ring(i + 1, k + 1), ring(i + 1, k));
      }
      mesh.faces.push_back({ring(m - 2, k), ring(m - 2, k + 1), top});  // top fan
    }
  }
  return mesh;
}
// [revolved_boundary]

/// Dimensions of a cup (all > 0): outer radius R, height H, wall thickness t < R and
/// bottom thickness b < H. The solid is the revolved profile
/// (0,0) -> (R,0) -> (R,H) -> (R-t,H) -> (R-t,b) -> (0,b): its cavity (r < R - t, z > b) is
/// outside the body although it lies inside the convex hull.
struct CupDimensions {
  double outerRadius = 0.5;
  double height = 0.8;
  double wallThickness = 0.1;
  double bottomThickness = 0.1;
};

/// The cup (3D) or its U-shaped cross-section (2D), centred on its bounding box.
/// Profile segments are split into pieces no longer than maxProfileSpacing.
template <int D>
SurfaceMesh<D> cupBoundary(const CupDimensions& cup = {}, int segments = 48,
                           double maxProfileSpacing = 0.05) {
  const char* fn = "cupBoundary";
  detail::requirePositiveLength(fn, "outerRadius", cup.outerRadius);
  detail::requirePositiveLength(fn, "height", cup.height);
  detail::requirePositiveLength(fn, "wallThickness", cup.wallThickness);
  detail::requirePositiveLength(fn, "bottomThickness", cup.bottomThickness);
  detail::requirePositiveLength(fn, "maxProfileSpacing", maxProfileSpacing);
  detail::requireNonconvex(cup.wallThickness < cup.outerRadius, fn,
                           "wallThickness must be smaller than outerRadius");
  detail::requireNonconvex(cup.bottomThickness < cup.height, fn,
                           "bottomThickness must be smaller than height");
  const double R = cup.outerRadius, H = cup.height, t = cup.wallThickness,
               b = cup.bottomThickness;
  const std::vector<Vec2> corners = {Vec2(0, 0),     Vec2(R, 0),     Vec2(R, H),
                                     Vec2(R - t, H), Vec2(R - t, b), Vec2(0, b)};
  SurfaceMesh<D> mesh =
      revolvedBoundary<D>(detail::refinePolyline(corners, maxProfileSpacing), segments);
  detail::centreOnBounds<D>(mesh);
  return mesh;
}

/// The 2D cup: a U of outer width 2R, height H, wall t and bottom b.
inline Polygon uPolygon(const CupDimensions& cup = {}, double maxSpacing = 0.05) {
  return cupBoundary<2>(cup, 3, maxSpacing);
}

/// Dimensions of a bone: two balls of radius ballRadius whose centres are `length` apart
/// on the z axis, joined by a neck (cylinder) of radius neckRadius <= ballRadius.
/// The neck meets each ball on the circle r = neckRadius, at height
/// sqrt(ballRadius^2 - neckRadius^2) from the ball's centre toward the other ball, so
/// length must be at least twice that height.
struct BoneDimensions {
  double ballRadius = 0.3;
  double neckRadius = 0.12;
  double length = 1.2;
};

// [bone_profile]
/// The profile of a bone in the (r, z) half-plane, bottom pole to top pole, centred at
/// z = 0: an arc of the bottom ball, the neck, an arc of the top ball. Points on the arcs
/// lie exactly on the balls, so the revolved vertices lie on the smooth bone.
inline std::vector<Vec2> boneProfile(const BoneDimensions& bone, double maxProfileSpacing) {
  const char* fn = "boneProfile";
  detail::requirePositiveLength(fn, "ballRadius", bone.ballRadius);
  detail::requirePositiveLength(fn, "neckRadius", bone.neckRadius);
  detail::requirePositiveLength(fn, "length", bone.length);
  detail::requirePositiveLength(fn, "maxProfileSpacing", maxProfileSpacing);
  const double Rb = bone.ballRadius, rn = bone.neckRadius, half = 0.5 * bone.length;
  detail::requireNonconvex(rn <= Rb, fn, "neckRadius must not exceed ballRadius");
  const double rise = std::sqrt(Rb * Rb - rn * rn);  // junction height above a ball centre
  detail::requireNonconvex(half >= rise, fn,
                           "length must be at least 2 sqrt(ballRadius^2 - neckRadius^2), "
                           "or the balls overlap past the neck");
  const double junction = std::acos(rn / Rb);  // polar angle of the junction on a ball
  std::vector<Vec2> profile;
  const auto arc = [&](double centreZ, double from, double to) {
    const int pieces =
        std::max(2, static_cast<int>(std::ceil(Rb * (to - from) / maxProfileSpacing)));
    for (int s = 0; s < pieces; ++s) {
      const double angle = from + (to - from) * s / pieces;
      profile.push_back(Vec2(Rb * std::cos(angle), centreZ + Rb * std::sin(angle)));
    }
  };
  arc(-half, -0.5 * M_PI, junction);  // bottom ball, from its pole up to the neck
  profile.front().x() = 0.0;          // the pole exactly on the axis
  if (half > rise) {  // a neck of positive length (none when the balls meet at the neck)
    const Vec2 neckBottom(rn, -half + rise), neckTop(rn, half - rise);
    const std::vector<Vec2> neck =
        detail::refinePolyline({neckBottom, neckTop}, maxProfileSpacing);
    profile.insert(profile.end(), neck.begin(), neck.end() - 1);
  }
  arc(half, -junction, 0.5 * M_PI);   // top ball, from the neck up to its pole
  profile.push_back(Vec2(0.0, half + Rb));
  return profile;
}
// [bone_profile]

/// The bone (3D) or the dumbbell outline (2D).
template <int D>
SurfaceMesh<D> boneBoundary(const BoneDimensions& bone = {}, int segments = 48,
                            double maxProfileSpacing = 0.04) {
  return revolvedBoundary<D>(boneProfile(bone, maxProfileSpacing), segments);
}

/// A capsule: the points within `radius` of the segment from -halfLength to +halfLength on
/// the z axis (3D), or on the y axis (2D, a stadium). It is the bone with
/// neckRadius = ballRadius.
template <int D>
SurfaceMesh<D> capsuleBoundary(double halfLength, double radius, int segments = 48,
                               double maxProfileSpacing = 0.05) {
  detail::requirePositiveLength("capsuleBoundary", "halfLength", halfLength);
  detail::requirePositiveLength("capsuleBoundary", "radius", radius);
  return boneBoundary<D>(BoneDimensions{radius, radius, 2.0 * halfLength}, segments,
                         maxProfileSpacing);
}

/// An annulus (2D ring): the points at distance at most minorRadius from the circle of
/// radius majorRadius, i.e. majorRadius - minorRadius <= |x| <= majorRadius + minorRadius.
/// It is the z = 0 section of the torus with the same radii. Two loops of `segments`
/// vertices on the two circles: the outer one counterclockwise, the inner one clockwise.
inline Polygon annulusPolygon(double majorRadius, double minorRadius, int segments = 64) {
  const char* fn = "annulusPolygon";
  detail::requirePositiveLength(fn, "majorRadius", majorRadius);
  detail::requirePositiveLength(fn, "minorRadius", minorRadius);
  detail::requireCountAtLeast(fn, "segments", segments, 3);
  detail::requireNonconvex(minorRadius < majorRadius, fn,
                           "minorRadius must be smaller than majorRadius");
  Polygon ring;
  for (int loop = 0; loop < 2; ++loop) {
    const double radius = loop == 0 ? majorRadius + minorRadius : majorRadius - minorRadius;
    const int first = static_cast<int>(ring.vertices.size());
    for (int k = 0; k < segments; ++k) {
      const double angle = 2.0 * M_PI * k / segments;
      ring.vertices.push_back(Vec2(radius * std::cos(angle), radius * std::sin(angle)));
    }
    for (int k = 0; k < segments; ++k) {
      const int a = first + k, b = first + (k + 1) % segments;
      if (loop == 0) {
        ring.faces.push_back({a, b});  // outer circle: counterclockwise
      } else {
        ring.faces.push_back({b, a});  // inner circle: clockwise (the hole is outside)
      }
    }
  }
  return ring;
}

/// The ring: a torus (3D, chapter 5's torusMesh with minorSegments around the tube) or an
/// annulus (2D), with `segments` vertices around the axis.
template <int D>
SurfaceMesh<D> ringBoundary(double majorRadius, double minorRadius, int segments = 48,
                            int minorSegments = 24) {
  if constexpr (D == 2) {
    (void)minorSegments;
    return annulusPolygon(majorRadius, minorRadius, segments);
  } else {
    return torusMesh(majorRadius, minorRadius, segments, minorSegments);
  }
}

/// A star with `points` tips on the circle of radius outerRadius and notches on the circle
/// of radius innerRadius < outerRadius, the first tip on the +y axis; each edge split into
/// `subdivisions` segments. Counterclockwise.
inline Polygon starPolygon(double outerRadius = 0.5, double innerRadius = 0.2, int points = 5,
                           int subdivisions = 4) {
  const char* fn = "starPolygon";
  detail::requirePositiveLength(fn, "outerRadius", outerRadius);
  detail::requirePositiveLength(fn, "innerRadius", innerRadius);
  detail::requireCountAtLeast(fn, "points", points, 2);
  detail::requireCountAtLeast(fn, "subdivisions", subdivisions, 1);
  detail::requireNonconvex(innerRadius < outerRadius, fn,
                           "innerRadius must be smaller than outerRadius");
  std::vector<Vec2> corners;
  for (int k = 0; k < 2 * points; ++k) {
    const double angle = 0.5 * M_PI + M_PI * k / points;
    const double radius = k % 2 == 0 ? outerRadius : innerRadius;
    corners.push_back(Vec2(radius * std::cos(angle), radius * std::sin(angle)));
  }
  std::vector<Vec2> loop;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
    for (int s = 0; s < subdivisions; ++s) loop.push_back(a + (b - a) * (double(s) / subdivisions));
  }
  return polygonFromLoop(loop);
}

}  // namespace stackbook
