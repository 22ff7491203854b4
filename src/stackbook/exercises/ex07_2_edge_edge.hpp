#pragma once
/// \file
/// \brief Exercise 7.2: an edge-edge test that finds crossed edges without denser surface
/// samples (\ref ch07).

#include <algorithm>
#include <array>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/surface_mesh.hpp"

namespace stackbook {

/// The edges of a triangle mesh, each once, as (i, j) with i < j, sorted.
inline std::vector<std::array<int, 2>> meshEdges(const TriangleMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  for (const std::array<int, 3>& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const int a = f[static_cast<std::size_t>(k)], b = f[static_cast<std::size_t>((k + 1) % 3)];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

/// Edge-edge interference of the pair (3D). meshFirst and meshSecond are the boundary
/// meshes of bodies[pair.first] and bodies[pair.second] in their body frames. For every
/// edge e of the first mesh whose world box meets the second body's worldBounds(), and
/// every edge f of the second mesh whose world box meets the first body's (an edge that
/// misses the other body's box cannot enter it), take the closest points p (on e) and q
/// (on f) of the two segments at the bodies' poses:
///  - if phi_second(p) < 0, record a sample at p owned by the first body (other = second,
///    depth phi_second(p), normal N_second(p) in world, sampleIndex = index of e in
///    meshEdges(meshFirst));
///  - if phi_first(q) < 0, record one at q owned by the second body, the same way.
/// Samples come in the order of (e, f) pairs, e outer, and within a pair p before q.
/// counters->phiQueries counts the phi evaluations. Throws std::invalid_argument when
/// the pair does not name two different bodies.
std::vector<InterferenceSample<3>> edgeEdgeInterference(const std::vector<CollisionBody<3>>& bodies,
                                                        const BodyPair& pair,
                                                        const TriangleMesh& meshFirst,
                                                        const TriangleMesh& meshSecond,
                                                        DetectionCounters* counters = nullptr);

}  // namespace stackbook
