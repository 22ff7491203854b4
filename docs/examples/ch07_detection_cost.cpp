// Prints chapter 7's cost tables, in counted operations (the same on every machine):
// how many box tests sweep and prune makes against testing all pairs, for scattered bodies,
// a tall stack and a pile on a ground; how many phi queries the body-frame box test
// saves the narrow phase on three contacts; and how far a grid phi is from the exact one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

namespace {

using namespace stackbook;

/// Portable uniform numbers in [lo, hi) (splitmix64), the same on every platform.
struct Uniform {
  unsigned long long state;
  double operator()(double lo, double hi) {
    state += 0x9E3779B97F4A7C15ull;
    unsigned long long z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

BroadPhaseProxy<3> cube(const Vec3& centre, double half, bool isStatic = false) {
  return {Aabb<3>{Vec3(centre.array() - half), Vec3(centre.array() + half)}, isStatic};
}

/// n cubes of side 0.2 to 1 scattered in a cube of volume n / 0.5 (half a body per unit
/// volume): each overlaps a few neighbours.
std::vector<BroadPhaseProxy<3>> scattered(int n) {
  Uniform uniform{7};
  const double side = std::cbrt(n / 0.5);
  std::vector<BroadPhaseProxy<3>> proxies;
  for (int i = 0; i < n; ++i) {
    const Vec3 c(uniform(0.0, side), uniform(0.0, side), uniform(0.0, side));
    proxies.push_back(cube(c, uniform(0.1, 0.5)));
  }
  return proxies;
}

/// n unit cubes in one column along z, each resting 0.01 into the one below.
std::vector<BroadPhaseProxy<3>> stack(int n) {
  std::vector<BroadPhaseProxy<3>> proxies;
  for (int i = 0; i < n; ++i) proxies.push_back(cube(Vec3(0.0, 0.0, 0.5 + 0.99 * i), 0.5));
  return proxies;
}

/// A static ground 0.5 thick under a square of sqrt(n) x sqrt(n) columns of 10 unit cubes
/// 1.5 apart (n cubes in all).
std::vector<BroadPhaseProxy<3>> pile(int n) {
  const int columns = static_cast<int>(std::lround(std::sqrt(n / 10.0)));
  const double width = 1.5 * columns + 2.0;
  std::vector<BroadPhaseProxy<3>> proxies = {
      {Aabb<3>{Vec3(-1.0, -1.0, -0.5), Vec3(width, width, 0.0)}, true}};
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < columns; ++j) {
      for (int k = 0; k < 10; ++k) {
        proxies.push_back(cube(Vec3(1.5 * i, 1.5 * j, 0.49 + 0.99 * k), 0.5));
      }
    }
  }
  return proxies;
}

void broadPhaseRow(const char* scene, const std::vector<BroadPhaseProxy<3>>& proxies) {
  DetectionCounters automatic, alongX, brute;
  const std::vector<BodyPair> pairs = sweepAndPrune<3>(proxies, {}, &automatic);
  sweepAndPrune<3>(proxies, {0, 0.0}, &alongX);
  allPairs<3>(proxies, {}, &brute);
  const char axes[] = {'x', 'y', 'z'};
  std::printf("| %s | %zu | %zu | %c: %lld | %lld | %lld |\n", scene, proxies.size(), pairs.size(),
              axes[sweepAxis<3>(proxies)], static_cast<long long>(automatic.pairsTested),
              static_cast<long long>(alongX.pairsTested),
              static_cast<long long>(brute.pairsTested));
}

void broadPhase() {
  std::printf("| scene | bodies n | overlapping pairs | sweep and prune, automatic axis: box "
              "tests | sweep along x: box tests | all pairs: box tests |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const int n : {10, 100, 1000, 10000}) broadPhaseRow("scattered", scattered(n));
  for (const int n : {10, 100, 1000}) broadPhaseRow("one stack", stack(n));
  for (const int n : {90, 1000, 10000}) broadPhaseRow("pile on a ground", pile(n));
  std::printf("\n");
}

void narrowRow(const char* what, const std::vector<CollisionBody<3>>& bodies) {
  DetectionCounters culled, unculled;
  NarrowPhaseSettings noCull;
  noCull.cullByBounds = false;
  const std::size_t found = pairInterference<3>(bodies, {0, 1}, {}, &culled).size();
  pairInterference<3>(bodies, {0, 1}, noCull, &unculled);
  std::printf("| %s | %lld | %lld | %lld | %lld | %zu |\n", what,
              static_cast<long long>(culled.samplesTransformed),
              static_cast<long long>(culled.samplesCulled), static_cast<long long>(culled.phiQueries),
              static_cast<long long>(unculled.phiQueries), found);
}

void narrowPhase() {
  std::printf("| contact (3D) | samples transformed | culled by the box | phi queries with "
              "the box test | phi queries without | samples inside |\n");
  std::printf("|---|---|---|---|---|---|\n");
  {  // A cube, each edge in 4 pieces, 0.01 deep on a ground 10 x 10 x 1 in 32 pieces.
    const BoxShape<3> ground(BoxSdf<3>(Vec3(5.0, 5.0, 0.5)), boxMesh(Vec3(10.0, 10.0, 1.0), 32));
    const BoxShape<3> box(BoxSdf<3>(Vec3::Constant(0.5)), boxMesh(Vec3::Ones(), 4));
    const RigidBody<3> g = makeStaticBody<3>(Vec3(0.0, 0.0, -0.5));
    const RigidBody<3> b = makeStaticBody<3>(Vec3(0.1, 0.2, 0.49));
    narrowRow("cube on a dense ground", {collisionBody<3>(b, box), collisionBody<3>(g, ground)});
  }
  {  // Chapter 6's grid torus (R = 1, r = 0.2) slid against a peg 0.2 x 0.2 x 3.
    const GridShape<3> ring(ringBoundary<3>(1.0, 0.2, 48, 24), "ring");
    const BoxShape<3> peg(BoxSdf<3>(Vec3(0.1, 0.1, 1.5)), boxMesh(Vec3(0.2, 0.2, 3.0), 8));
    const RigidBody<3> r = makeStaticBody<3>(Vec3(0.75, 0.0, 0.0));
    const RigidBody<3> p = makeStaticBody<3>();
    narrowRow("grid ring touching a peg", {collisionBody<3>(r, ring), collisionBody<3>(p, peg)});
  }
  {  // Chapter 6's grid cup (R = 1, H = 1.5, wall 0.2, bottom 0.3), a ball 0.02 into its floor.
    const GridShape<3> cup(cupBoundary<3>(CupDimensions{1.0, 1.5, 0.2, 0.3}), "cup");
    const SphereShape<3> ball(SphereSdf<3>(0.5), icosphereMesh(0.5, 3));
    const RigidBody<3> c = makeStaticBody<3>();
    const RigidBody<3> b = makeStaticBody<3>(Vec3(0.0, 0.0, -0.45 + 0.5 - 0.02));
    narrowRow("ball in a grid cup", {collisionBody<3>(b, ball), collisionBody<3>(c, cup)});
  }
  std::printf("\n");
}

/// The error of chapter 6's grid of the torus mesh (R = 1, r = 0.2, 48 x 24 vertices)
/// against the exact torus distance, on 2000 points within 0.1 of the surface, as the test
/// `a ring with a grid signed distance threads on a peg as the exact ring does` measures it.
void gridError() {
  const TorusSdf<3> exact(1.0, 0.2);
  const std::vector<Vec3> band = sampleBand<3>(
      [&](const Vec3& x) { return exact.distance(x); }, exact.bounds().inflated(0.1), -0.1, 0.1,
      2000, 7);
  std::printf("| torus grid, cells across | cell size h | max error of phi within 0.1 of the "
              "surface |\n");
  std::printf("|---|---|---|\n");
  for (const int cells : {16, 32, 64}) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    const GridShape<3> ring(ringBoundary<3>(1.0, 0.2, 48, 24), "ring", settings);
    double worst = 0.0;
    for (const Vec3& x : band) {
      worst = std::max(worst, std::abs(ring.signedDistance(x) - exact.distance(x)));
    }
    std::printf("| %d | %.6g | %.6f |\n", cells, ring.grid().cellSize(), worst);
  }
  std::printf("\nThe error cannot fall below that of the mesh itself: 48 x 24 flat facets "
              "inscribed in the torus, whose edges cut inside it by up to r (1 - cos(pi/24)) = "
              "%.6f around the tube and (R + r)(1 - cos(pi/48)) = %.6f around the axis.\n\n",
              0.2 * (1.0 - std::cos(M_PI / 24.0)), 1.2 * (1.0 - std::cos(M_PI / 48.0)));
}

}  // namespace

int main() {
  broadPhase();
  narrowPhase();
  gridError();
}
