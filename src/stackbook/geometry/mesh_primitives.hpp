#pragma once
/// \file
/// \brief Procedural closed, outward-oriented boundary meshes: boxes, icospheres, tori and
/// cylinders in 3D; rectangles and regular polygons in 2D (\ref ch05).
///
/// Every generator returns a watertight SurfaceMesh<D> (each edge shared by exactly two
/// triangles in 3D, each vertex by exactly two segments in 2D) oriented as surface_mesh.hpp
/// requires: in 3D a triangle (a, b, c) has outward normal (b - a) x (c - a); in 2D the
/// boundary runs counterclockwise (the body on the left of each segment (a, b)).
/// All shapes are centred at the origin; the 3D solids of revolution have the z axis as axis.
/// Chapter 5 computes their mass properties; chapters 6 and 7 use their vertices as surface
/// samples, which is why boxes and rectangles can be subdivided.
/// Bad arguments (non-positive or non-finite sizes, too few segments) throw
/// std::invalid_argument naming the function and the argument.

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook {

namespace detail {

inline void requirePositiveLength(const char* function, const char* name, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    std::ostringstream msg;
    msg << function << ": " << name << " must be finite and positive, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

inline void requireCountAtLeast(const char* function, const char* name, int value, int least) {
  if (value < least) {
    std::ostringstream msg;
    msg << function << ": " << name << " must be at least " << least << ", got " << value;
    throw std::invalid_argument(msg.str());
  }
}

/// Append the quad (a, b, c, d), counterclockwise seen from outside, as two triangles.
inline void appendQuad(TriangleMesh& mesh, int a, int b, int c, int d) {
  mesh.faces.push_back({a, b, c});
  mesh.faces.push_back({a, c, d});
}

}  // namespace detail

/// A box with side lengths size = (sx, sy, sz), centred at the origin, axis-aligned.
/// Each face is split into an n x n grid of quads (two triangles each), with the grid
/// vertices shared between neighbouring faces: 6 n^2 + 2 vertices, 12 n^2 triangles.
/// n = 1 gives the usual 8-vertex, 12-triangle box.
inline TriangleMesh boxMesh(const Vec3& size, int subdivisions = 1) {
  for (int a = 0; a < 3; ++a) {
    static const char* const names[3] = {"size.x", "size.y", "size.z"};
    detail::requirePositiveLength("boxMesh", names[a], size[a]);
  }
  detail::requireCountAtLeast("boxMesh", "subdivisions", subdivisions, 1);
  const int n = subdivisions;
  TriangleMesh mesh;
  // Lattice points (i, j, k) in [0, n]^3 that lie on the boundary of the cube, numbered
  // in lexicographic order; interior lattice points get no vertex.
  std::vector<int> index(static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1)), -1);
  const auto slot = [n](int i, int j, int k) {
    return static_cast<std::size_t>((i * (n + 1) + j) * (n + 1) + k);
  };
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      for (int k = 0; k <= n; ++k) {
        const bool onBoundary = i == 0 || i == n || j == 0 || j == n || k == 0 || k == n;
        if (!onBoundary) continue;
        index[slot(i, j, k)] = static_cast<int>(mesh.vertices.size());
        const Vec3 t(double(i) / n, double(j) / n, double(k) / n);
        mesh.vertices.push_back(Vec3((t.array() - 0.5) * size.array()));
      }
    }
  }
  // Face with normal +-e_a. With u = a+1, v = a+2 (mod 3), e_u x e_v = e_a, so the quad
  // (u, v) -> (u+1, v) -> (u+1, v+1) -> (u, v+1) is counterclockwise seen from +e_a.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const int level = side == 0 ? 0 : n;
      const auto vertexAt = [&](int p, int q) {
        std::array<int, 3> ijk{};
        ijk[static_cast<std::size_t>(a)] = level;
        ijk[static_cast<std::size_t>(u)] = p;
        ijk[static_cast<std::size_t>(v)] = q;
        return index[slot(ijk[0], ijk[1], ijk[2])];
      };
      for (int p = 0; p < n; ++p) {
        for (int q = 0; q < n; ++q) {
          const int c00 = vertexAt(p, q), c10 = vertexAt(p + 1, q);
          const int c11 = vertexAt(p + 1, q + 1), c01 = vertexAt(p, q + 1);
          if (side == 1) {
            detail::appendQuad(mesh, c00, c10, c11, c01);  // outward normal +e_a
          } else {
            detail::appendQuad(mesh, c00, c01, c11, c10);  // outward normal -e_a
          }
        }
      }
    }
  }
  return mesh;
}

/// A sphere of the given radius approximated by an icosphere: the regular icosahedron with
/// each triangle split into four `level` times, every new vertex pushed out onto the sphere.
/// All vertices lie on the sphere (inscribed polyhedron): 10 * 4^level + 2 vertices,
/// 20 * 4^level triangles. The enclosed volume approaches 4/3 pi r^3 from below with an
/// error proportional to the squared edge length, i.e. falling by 4 per level (\ref ch05).
inline TriangleMesh icosphereMesh(double radius, int level = 2) {
  detail::requirePositiveLength("icosphereMesh", "radius", radius);
  detail::requireCountAtLeast("icosphereMesh", "level", level, 0);
  if (level > 8) {
    std::ostringstream msg;
    msg << "icosphereMesh: level must be at most 8 (" << 20 * (1 << 16)
        << " triangles), got " << level;
    throw std::invalid_argument(msg.str());
  }
  TriangleMesh mesh;
  // The 12 icosahedron vertices are the cyclic permutations of (0, +-1, +-phi).
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  const double raw[12][3] = {{-1, phi, 0}, {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0},
                             {0, -1, phi}, {0, 1, phi},  {0, -1, -phi}, {0, 1, -phi},
                             {phi, 0, -1}, {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (const auto& p : raw) mesh.vertices.push_back(Vec3(p[0], p[1], p[2]).normalized());
  mesh.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    // Midpoint of each edge, created once and shared by the two triangles of the edge.
    // An ordered map keeps the vertex numbering deterministic.
    std::map<std::pair<int, int>, int> midpoint;
    const auto midpointOf = [&](int a, int b) {
      const std::pair<int, int> key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
      const auto found = midpoint.find(key);
      if (found != midpoint.end()) return found->second;
      const Vec3 m = (mesh.vertices[static_cast<std::size_t>(a)] +
                      mesh.vertices[static_cast<std::size_t>(b)]).normalized();
      const int id = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(m);
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> refined;
    refined.reserve(mesh.faces.size() * 4);
    for (const std::array<int, 3>& f : mesh.faces) {
      const int ab = midpointOf(f[0], f[1]), bc = midpointOf(f[1], f[2]);
      const int ca = midpointOf(f[2], f[0]);
      refined.push_back({f[0], ab, ca});
      refined.push_back({f[1], bc, ab});
      refined.push_back({f[2], ca, bc});
      refined.push_back({ab, bc, ca});
    }
    mesh.faces = std::move(refined);
  }
  for (Vec3& p : mesh.vertices) p *= radius;
  return mesh;
}

/// A ring torus about the z axis: tube centre circle of radius majorRadius in the xy plane,
/// tube radius minorRadius < majorRadius. The surface point at angles (u, v) is
/// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), sampled at majorSegments values of u
/// and minorSegments values of v: majorSegments * minorSegments vertices, twice as many
/// triangles. The mesh is inscribed in the smooth torus (all vertices on it).
inline TriangleMesh torusMesh(double majorRadius, double minorRadius, int majorSegments = 48,
                              int minorSegments = 24) {
  detail::requirePositiveLength("torusMesh", "majorRadius", majorRadius);
  detail::requirePositiveLength("torusMesh", "minorRadius", minorRadius);
  if (!(minorRadius < majorRadius)) {
    std::ostringstream msg;
    msg << "torusMesh: minorRadius (" << minorRadius << ") must be smaller than majorRadius ("
        << majorRadius << ") for a ring torus";
    throw std::invalid_argument(msg.str());
  }
  detail::requireCountAtLeast("torusMesh", "majorSegments", majorSegments, 3);
  detail::requireCountAtLeast("torusMesh", "minorSegments", minorSegments, 3);
  TriangleMesh mesh;
  const double twoPi = 2.0 * M_PI;
  for (int i = 0; i < majorSegments; ++i) {
    const double u = twoPi * i / majorSegments;
    for (int j = 0; j < minorSegments; ++j) {
      const double v = twoPi * j / minorSegments;
      const double rho = majorRadius + minorRadius * std::cos(v);
      mesh.vertices.push_back(
          Vec3(rho * std::cos(u), rho * std::sin(u), minorRadius * std::sin(v)));
    }
  }
  // dP/du x dP/dv points along the outward tube normal (cos v cos u, cos v sin u, sin v),
  // so the quad (i, j) -> (i+1, j) -> (i+1, j+1) -> (i, j+1) is outward-oriented.
  const auto id = [&](int i, int j) {
    return (i % majorSegments) * minorSegments + (j % minorSegments);
  };
  for (int i = 0; i < majorSegments; ++i) {
    for (int j = 0; j < minorSegments; ++j) {
      detail::appendQuad(mesh, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return mesh;
}

/// A closed cylinder about the z axis, centred at the origin: radius, height, `segments`
/// vertices around each circle, `stacks` bands along the axis, and `capRings` concentric
/// rings on each cap (1: a fan of triangles around the cap centre). The vertices lie on the
/// smooth cylinder (inscribed prism).
inline TriangleMesh cylinderMesh(double radius, double height, int segments = 32, int stacks = 1,
                                 int capRings = 1) {
  detail::requirePositiveLength("cylinderMesh", "radius", radius);
  detail::requirePositiveLength("cylinderMesh", "height", height);
  detail::requireCountAtLeast("cylinderMesh", "segments", segments, 3);
  detail::requireCountAtLeast("cylinderMesh", "stacks", stacks, 1);
  detail::requireCountAtLeast("cylinderMesh", "capRings", capRings, 1);
  TriangleMesh mesh;
  const double twoPi = 2.0 * M_PI;
  // Side rings k = 0..stacks, bottom (z = -h/2) to top (z = +h/2).
  for (int k = 0; k <= stacks; ++k) {
    const double z = height * (double(k) / stacks - 0.5);
    for (int i = 0; i < segments; ++i) {
      const double u = twoPi * i / segments;
      mesh.vertices.push_back(Vec3(radius * std::cos(u), radius * std::sin(u), z));
    }
  }
  const auto side = [&](int k, int i) { return k * segments + (i % segments); };
  // dP/du x dP/dz = r (cos u, sin u, 0): outward.
  for (int k = 0; k < stacks; ++k) {
    for (int i = 0; i < segments; ++i) {
      detail::appendQuad(mesh, side(k, i), side(k, i + 1), side(k + 1, i + 1), side(k + 1, i));
    }
  }
  // Caps: inner rings m = 1..capRings-1 (the outermost ring is the side ring) and a centre.
  for (int top = 0; top < 2; ++top) {
    const double z = top ? 0.5 * height : -0.5 * height;
    const int outer = top ? stacks : 0;
    std::vector<int> ringStart(static_cast<std::size_t>(capRings + 1), 0);
    ringStart[static_cast<std::size_t>(capRings)] = outer * segments;
    for (int m = 1; m < capRings; ++m) {
      ringStart[static_cast<std::size_t>(m)] = static_cast<int>(mesh.vertices.size());
      const double rm = radius * m / capRings;
      for (int i = 0; i < segments; ++i) {
        const double u = twoPi * i / segments;
        mesh.vertices.push_back(Vec3(rm * std::cos(u), rm * std::sin(u), z));
      }
    }
    const int centre = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(Vec3(0.0, 0.0, z));
    const auto ring = [&](int m, int i) {
      return ringStart[static_cast<std::size_t>(m)] + (i % segments);
    };
    // Seen from +z, radial-then-tangential is counterclockwise (e_r x e_t = +e_z):
    // keep that order on the top cap and reverse it on the bottom cap.
    for (int i = 0; i < segments; ++i) {
      if (top) {
        mesh.faces.push_back({centre, ring(1, i), ring(1, i + 1)});
      } else {
        mesh.faces.push_back({centre, ring(1, i + 1), ring(1, i)});
      }
      for (int m = 1; m < capRings; ++m) {
        if (top) {
          detail::appendQuad(mesh, ring(m, i), ring(m + 1, i), ring(m + 1, i + 1),
                             ring(m, i + 1));
        } else {
          detail::appendQuad(mesh, ring(m, i), ring(m, i + 1), ring(m + 1, i + 1),
                             ring(m + 1, i));
        }
      }
    }
  }
  return mesh;
}

/// A closed polygon through the given vertices in order; faces (k, k+1) and (n-1, 0).
/// The loop must run counterclockwise for the polygon to be outward-oriented.
inline Polygon polygonFromLoop(const std::vector<Vec2>& loop) {
  detail::requireCountAtLeast("polygonFromLoop", "number of vertices",
                              static_cast<int>(loop.size()), 3);
  Polygon polygon;
  polygon.vertices = loop;
  const int n = static_cast<int>(loop.size());
  for (int k = 0; k < n; ++k) polygon.faces.push_back({k, (k + 1) % n});
  return polygon;
}

/// A rectangle with side lengths size = (sx, sy), centred at the origin, counterclockwise
/// from the corner (-sx/2, -sy/2). Each side is split into `subdivisions` equal segments:
/// 4 * subdivisions vertices and segments.
inline Polygon rectanglePolygon(const Vec2& size, int subdivisions = 1) {
  detail::requirePositiveLength("rectanglePolygon", "size.x", size.x());
  detail::requirePositiveLength("rectanglePolygon", "size.y", size.y());
  detail::requireCountAtLeast("rectanglePolygon", "subdivisions", subdivisions, 1);
  const Vec2 h = 0.5 * size;
  const std::array<Vec2, 4> corners = {Vec2(-h.x(), -h.y()), Vec2(h.x(), -h.y()),
                                       Vec2(h.x(), h.y()), Vec2(-h.x(), h.y())};
  std::vector<Vec2> loop;
  for (std::size_t c = 0; c < 4; ++c) {
    const Vec2& a = corners[c];
    const Vec2& b = corners[(c + 1) % 4];
    for (int s = 0; s < subdivisions; ++s) loop.push_back(a + (b - a) * (double(s) / subdivisions));
  }
  return polygonFromLoop(loop);
}

/// A regular polygon with `sides` vertices on the circle of the given radius (inscribed),
/// counterclockwise from (radius, 0). Its area approaches pi r^2 from below as
/// (sides/2) r^2 sin(2 pi / sides), an error falling as 1/sides^2 (\ref ch05).
inline Polygon regularPolygon(double radius, int sides) {
  detail::requirePositiveLength("regularPolygon", "radius", radius);
  detail::requireCountAtLeast("regularPolygon", "sides", sides, 3);
  std::vector<Vec2> loop;
  for (int k = 0; k < sides; ++k) {
    const double t = 2.0 * M_PI * k / sides;
    loop.push_back(Vec2(radius * std::cos(t), radius * std::sin(t)));
  }
  return polygonFromLoop(loop);
}

}  // namespace stackbook
