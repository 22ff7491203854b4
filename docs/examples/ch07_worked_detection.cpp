// Prints the worked examples of chapter 7 as Markdown: a unit cube resting 0.01 deep on a
// static ground (the samples found, both directions, and what the detection cost), and a
// tilted plank whose deepest corner is or is not approaching.
#include <cmath>
#include <cstdio>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"

namespace {

using namespace stackbook;

// A value rounded to the digits printed, without a "-0".
double shown(double x) { return std::abs(x) < 5e-13 ? 0.0 : x; }

void cubeOnGround() {
  const double d = 0.01;
  const BoxShape<3> groundShape(BoxSdf<3>(Vec3(5.0, 5.0, 0.5)), boxMesh(Vec3(10.0, 10.0, 1.0)));
  const BoxShape<3> cubeShape(BoxSdf<3>(Vec3::Constant(0.5)), boxMesh(Vec3::Ones()));
  const RigidBody<3> ground = makeStaticBody<3>(Vec3(0.0, 0.0, -0.5));
  RigidBody<3> cube = makeDynamicBody<3>(1.0, AngVec<3>::Constant(1.0 / 6.0));
  cube.position = Vec3(0.0, 0.0, 0.5 - d);
  cube.velocity = Vec3(0.0, 0.0, -1.0);
  const std::vector<CollisionBody<3>> bodies = {collisionBody<3>(cube, cubeShape),
                                                collisionBody<3>(ground, groundShape)};
  DetectionCounters counters;
  const std::vector<PairInterference<3>> found = detectInterference<3>(bodies, {}, &counters);
  const std::vector<InterferenceSample<3>> samples = found.at(0).samples;
  std::printf("A unit cube (body 0, 8 corner samples) rests %.2f deep on a static ground box "
              "10 x 10 x 1 (body 1, top face z = 0), falling at 1 m/s.\n\n", d);
  std::printf("| owner | sample | body-frame sample | world point | depth phi | normal N | "
              "u_rel . N |\n");
  std::printf("|-------|--------|-------------------|-------------|-----------|----------|"
              "-----------|\n");
  for (const InterferenceSample<3>& s : samples) {
    const Vec3 b = cubeShape.surfaceSamples()[static_cast<std::size_t>(s.sampleIndex)];
    std::printf("| %d | %d | (%g, %g, %g) | (%g, %g, %g) | %.12g | (%g, %g, %g) | %g |\n",
                s.owner, s.sampleIndex, b.x(), b.y(), b.z(), s.point.x(), s.point.y(),
                s.point.z(), s.depth, shown(s.normal.x()), shown(s.normal.y()),
                shown(s.normal.z()), normalRelativeVelocity<3>(s, bodies));
  }
  std::printf("\nWhat `detectInterference` did, from `DetectionCounters::summary()`:\n\n    %s\n\n",
              counters.summary().c_str());
  std::printf("The ground's 8 corners are 5 away from the cube and are culled by its box; "
              "the cube's 4 top corners are above the ground's box. Only the 4 bottom corners "
              "reach phi.\n\n");
}

void tiltedPlank() {
  // A plank 1 x 0.5 tilted by theta = 0.1 on a static ground (top face y = 0); its left
  // bottom corner 0.15 deep, the right one 0.15 - sin(theta) deep.
  const double theta = 0.1;
  const BoxShape<2> groundShape(BoxSdf<2>(Vec2(5.0, 0.5)), rectanglePolygon(Vec2(10.0, 1.0)));
  const BoxShape<2> plankShape(BoxSdf<2>(Vec2(0.5, 0.25)), rectanglePolygon(Vec2(1.0, 0.5)));
  const RigidBody<2> ground = makeStaticBody<2>(Vec2(0.0, -0.5));
  RigidBody<2> plank = makeDynamicBody<2>(1.0, AngVec<2>::Constant(0.1));
  plank.orientation = Eigen::Rotation2Dd(theta);
  plank.position = Vec2(0.0, -0.15 + 0.5 * std::sin(theta) + 0.25 * std::cos(theta));
  std::printf("A plank 1 x 0.5 tilted by 0.1 rad lies on a static ground (2D): its left bottom "
              "corner is 0.15 deep, its right one 0.15 - sin 0.1 deep. Five motions, and the "
              "sample `deepestApproachingSample` picks:\n\n");
  std::printf("| omega | v_up | left: depth, u_rel . N | right: depth, u_rel . N | picked |\n");
  std::printf("|-------|------|------------------------|-------------------------|--------|\n");
  const double cases[][2] = {{1.0, 0.0}, {-1.0, 0.0}, {0.2, -0.5}, {0.0, 0.1}, {0.0, 0.0}};
  for (const auto& c : cases) {
    plank.velocity = Vec2(0.0, c[1]);
    plank.setAngularVelocity(AngVec<2>::Constant(c[0]));
    const std::vector<CollisionBody<2>> bodies = {collisionBody<2>(plank, plankShape),
                                                  collisionBody<2>(ground, groundShape)};
    const std::vector<InterferenceSample<2>> samples = pairInterference<2>(bodies, {0, 1});
    double depth[2] = {0.0, 0.0}, un[2] = {0.0, 0.0};
    for (const InterferenceSample<2>& s : samples) {
      const int side = plankShape.surfaceSamples()[static_cast<std::size_t>(s.sampleIndex)].x() < 0.0 ? 0 : 1;
      depth[side] = s.depth;
      un[side] = normalRelativeVelocity<2>(s, bodies);
    }
    const std::optional<InterferenceSample<2>> best = deepestApproachingSample<2>(samples, bodies);
    const char* picked = "none";
    if (best) {
      picked = plankShape.surfaceSamples()[static_cast<std::size_t>(best->sampleIndex)].x() < 0.0
                   ? "left (deeper)"
                   : "right (shallower)";
    }
    std::printf("| %g | %g | %.6f, %+.6f | %.6f, %+.6f | %s |\n", c[0], c[1], depth[0],
                shown(un[0]), depth[1], shown(un[1]), picked);
  }
  std::printf("\n");
}

}  // namespace

int main() {
  cubeOnGround();
  tiltedPlank();
}
