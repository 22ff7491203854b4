// Exercise 7.3 (your answer goes here): see ex07_3_sample_tree.hpp and chapter 7.
// Implement: SampleTree and appendSamplesInsideWithTree. Delete every TODO(reader) comment once
// your code is in: while one is left, the exercise counts as not solved and its tests do not
// run.
#include "stackbook/exercises/ex07_3_sample_tree.hpp"

namespace stackbook {

template <int D>
SampleTree<D>::SampleTree(const std::vector<Vec<D>>& points, int leafSize) {
  // TODO(reader): build the tree (median split along the longest axis).
  (void)points;
  (void)leafSize;
}

template <int D>
std::vector<int> SampleTree<D>::query(const Aabb<D>& box, std::int64_t* pointsVisited) const {
  // TODO(reader): walk the nodes whose boxes overlap `box`; return the points inside it.
  (void)box;
  (void)pointsVisited;
  return {};
}

template <int D>
void appendSamplesInsideWithTree(const CollisionBody<D>& owner, const SampleTree<D>& ownerTree,
                                 int ownerIndex, const CollisionBody<D>& penetrated,
                                 int penetratedIndex, std::vector<InterferenceSample<D>>& out,
                                 const NarrowPhaseSettings& settings, DetectionCounters* counters) {
  // TODO(reader): query the tree with the penetrated body's box seen from the owner, then
  // treat only those samples as appendSamplesInside() treats every sample.
  (void)owner;
  (void)ownerTree;
  (void)ownerIndex;
  (void)penetrated;
  (void)penetratedIndex;
  (void)out;
  (void)settings;
  (void)counters;
}

template class SampleTree<2>;
template class SampleTree<3>;
template void appendSamplesInsideWithTree<2>(const CollisionBody<2>&, const SampleTree<2>&, int,
                                             const CollisionBody<2>&, int,
                                             std::vector<InterferenceSample<2>>&,
                                             const NarrowPhaseSettings&, DetectionCounters*);
template void appendSamplesInsideWithTree<3>(const CollisionBody<3>&, const SampleTree<3>&, int,
                                             const CollisionBody<3>&, int,
                                             std::vector<InterferenceSample<3>>&,
                                             const NarrowPhaseSettings&, DetectionCounters*);

}  // namespace stackbook
