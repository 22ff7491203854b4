// Explicit instantiation of chapter 7's collision templates for D = 2 and D = 3.
// Nothing here is called; it makes the compiler check every template in both dimensions,
// as src/stackbook/instantiate_2d_3d.cpp does for the earlier chapters.

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/collision/collision_body.hpp"
#include "stackbook/collision/detection_counters.hpp"
#include "stackbook/collision/narrow_phase.hpp"

namespace stackbook {

template struct CollisionBody<2>;
template struct CollisionBody<3>;
template struct BroadPhaseProxy<2>;
template struct BroadPhaseProxy<3>;
template struct InterferenceSample<2>;
template struct InterferenceSample<3>;
template struct PairInterference<2>;
template struct PairInterference<3>;

#define STACKBOOK_INSTANTIATE_COLLISION(D)                                                      \
  template CollisionBody<D> collisionBodyAt<D>(const RigidBody<D>&, const Shape<D>&,            \
                                               const Pose<D>&);                                 \
  template CollisionBody<D> collisionBody<D>(const RigidBody<D>&, const Shape<D>&);             \
  template void checkCollisionBody<D>(const CollisionBody<D>&, int, const char*);               \
  template Aabb<D> worldBounds<D>(const Shape<D>&, const Pose<D>&);                             \
  template Aabb<D> worldBoundsOfSamples<D>(const Shape<D>&, const Pose<D>&);                    \
  template std::vector<BroadPhaseProxy<D>> broadPhaseProxies<D>(                                \
      const std::vector<CollisionBody<D>>&);                                                    \
  template int sweepAxis<D>(const std::vector<BroadPhaseProxy<D>>&, const BroadPhaseSettings&); \
  template std::vector<BodyPair> sweepAndPrune<D>(const std::vector<BroadPhaseProxy<D>>&,       \
                                                  const BroadPhaseSettings&, DetectionCounters*); \
  template std::vector<BodyPair> sweepAndPrune<D>(const std::vector<CollisionBody<D>>&,         \
                                                  const BroadPhaseSettings&, DetectionCounters*); \
  template std::vector<BodyPair> allPairs<D>(const std::vector<BroadPhaseProxy<D>>&,            \
                                             const BroadPhaseSettings&, DetectionCounters*);    \
  template void appendSamplesInside<D>(const CollisionBody<D>&, int, const CollisionBody<D>&,   \
                                       int, std::vector<InterferenceSample<D>>&,                \
                                       const NarrowPhaseSettings&, DetectionCounters*);         \
  template std::vector<InterferenceSample<D>> pairInterference<D>(                              \
      const std::vector<CollisionBody<D>>&, const BodyPair&, const NarrowPhaseSettings&,        \
      DetectionCounters*);                                                                      \
  template Vec<D> sampleRelativeVelocity<D>(const InterferenceSample<D>&,                       \
                                            const std::vector<CollisionBody<D>>&);              \
  template double normalRelativeVelocity<D>(const InterferenceSample<D>&,                       \
                                            const std::vector<CollisionBody<D>>&);              \
  template std::optional<InterferenceSample<D>> deepestApproachingSample<D>(                    \
      const std::vector<InterferenceSample<D>>&, const std::vector<CollisionBody<D>>&, DetectionCounters*); \
  template std::vector<PairInterference<D>> detectInterference<D>(                              \
      const std::vector<CollisionBody<D>>&, const DetectionSettings&, DetectionCounters*);

STACKBOOK_INSTANTIATE_COLLISION(2)
STACKBOOK_INSTANTIATE_COLLISION(3)

#undef STACKBOOK_INSTANTIATE_COLLISION

}  // namespace stackbook
