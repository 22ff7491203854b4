// Run this now (chapter 7): two U-shaped bodies hooked into each other (as in the chapter's
// figure). detectInterference finds the samples of each inside the other; the program
// prints each one (owner, world point, depth, normal) and the detection counters.
#include <cstdio>
#include <numbers>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;

int main() {
  const GridShape<2> cup(uPolygon(), "cup");
  RigidBody<2> a = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
  RigidBody<2> b = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
  b.orientation = Eigen::Rotation2Dd(std::numbers::pi + 0.05);
  b.position = Vec2(0.62, 0.06);
  const std::vector<CollisionBody<2>> bodies = {collisionBody<2>(a, cup), collisionBody<2>(b, cup)};
  DetectionCounters counters;
  const std::vector<PairInterference<2>> found = detectInterference<2>(bodies, {}, &counters);
  std::printf("owner  point               depth      normal (way out)\n");
  for (const PairInterference<2>& pair : found) {
    for (const InterferenceSample<2>& s : pair.samples) {
      std::printf("%5d  (%7.4f, %7.4f)  %9.5f  (%7.4f, %7.4f)\n", s.owner, s.point.x(), s.point.y(), s.depth,
                  s.normal.x(), s.normal.y());
    }
  }
  std::printf("%s\n", counters.summary().c_str());
}
