// Exercise 7.2 (your answer goes here): see ex07_2_edge_edge.hpp and chapter 7.
// Implement: edgeEdgeInterference. Delete every TODO(reader) comment once your code is in: while
// one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex07_2_edge_edge.hpp"

namespace stackbook {

std::vector<InterferenceSample<3>> edgeEdgeInterference(const std::vector<CollisionBody<3>>& bodies,
                                                        const BodyPair& pair,
                                                        const TriangleMesh& meshFirst,
                                                        const TriangleMesh& meshSecond,
                                                        DetectionCounters* counters) {
  // TODO(reader): for every pair of edges, the closest points of the two segments; keep
  // each one that lies inside the other body (phi < 0) as an interference sample.
  (void)bodies;
  (void)pair;
  (void)meshFirst;
  (void)meshSecond;
  (void)counters;
  return {};
}

}  // namespace stackbook
