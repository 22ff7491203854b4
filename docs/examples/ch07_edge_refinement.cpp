// Prints chapter 7's table of edge-on-edge contact against sampling density: two bars
// crossed at 90 degrees, whose edges cross inside each other while no corner of either is
// inside the other. With corner samples only the narrow phase finds nothing; with every
// edge cut into n pieces it finds the crossing, to within half a sample spacing.
#include <cmath>
#include <cstdio>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"
#include "stackbook/geometry/analytic_sdf.hpp"

namespace {

using namespace stackbook;

constexpr double L = 1.0, a = 0.25, d = 0.05;

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

/// The two bars, the upper one's crossing point moved by (xi, eta).
template <int D>
void placeBars(double xi, double eta, RigidBody<D>& lower, RigidBody<D>& upper) {
  if constexpr (D == 2) {
    upper.position = Vec2(xi, eta);
    upper.orientation = Eigen::Rotation2Dd(M_PI / 2);
  } else {
    const Eigen::Quaterniond edgeUp(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));
    lower.position = Vec3(0.0, 0.0, -a * std::sqrt(2.0));
    lower.orientation = edgeUp;
    upper.position = Vec3(xi, eta, a * std::sqrt(2.0) - d);
    upper.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())) * edgeUp;
  }
}

/// The deepest phi of the pair (0 when nothing is inside) and the phi queries it took.
template <int D>
double deepestPhi(const Shape<D>& bar, const RigidBody<D>& lower, const RigidBody<D>& upper,
                  std::size_t* found, long long* queries) {
  const std::vector<CollisionBody<D>> bodies = {collisionBody<D>(lower, bar),
                                                collisionBody<D>(upper, bar)};
  DetectionCounters counters;
  const std::vector<InterferenceSample<D>> samples =
      pairInterference<D>(bodies, {0, 1}, {}, &counters);
  double deepest = 0.0;
  for (const InterferenceSample<D>& s : samples) deepest = std::min(deepest, s.depth);
  if (found != nullptr) *found = samples.size();
  if (queries != nullptr) *queries = counters.phiQueries;
  return deepest;
}

template <int D>
SurfaceMesh<D> barMesh(const Vec<D>& half, int n) {
  if constexpr (D == 2) {
    return rectanglePolygon(Vec2(2.0 * half), n);
  } else {
    return boxMesh(Vec3(2.0 * half), n);
  }
}

constexpr double xi = 0.237, eta = 0.311;

template <int D>
void table() {
  Vec<D> half = Vec<D>::Constant(a);
  half[0] = L;
  RigidBody<D> lower = makeStaticBody<D>(), upper = makeStaticBody<D>();
  placeBars<D>(xi, eta, lower, upper);
  const double exact = D == 2 ? -a : -d / std::sqrt(2.0);
  const double slope = D == 2 ? 1.0 : 1.0 / std::sqrt(2.0);
  if constexpr (D == 2) {
    std::printf("**2D: a plus sign.** Two bars 2 x 0.5, the second turned 90 degrees and "
                "centred at (%g, %g). The deepest boundary point of either bar inside the "
                "other is the middle of an edge, %g deep.\n\n", xi, eta, a);
  } else {
    std::printf("**3D: crossed edges.** Two bars 2 x 0.5 x 0.5, each turned 45 degrees about "
                "its axis so that an edge faces the other, crossed at 90 degrees and "
                "overlapping by d = %g where the edges cross, at (%g, 0). The crossing point is "
                "the deepest point: d / sqrt 2 = %.6f from the other bar's faces.\n\n",
                d, xi, -exact);
  }
  std::printf("| pieces per edge n | samples per bar | spacing h = 2/n | phi queries | samples "
              "inside | deepest phi | error | bound %sh/2 |\n",
              D == 2 ? "" : "(1/sqrt 2) ");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const int n : {1, 2, 4, 8, 16, 32, 64, 128}) {
    SurfaceMesh<D> mesh = barMesh<D>(half, n);
    const std::size_t count = mesh.vertices.size();
    const AnalyticShape<D, BoxSdf<D>> bar(BoxSdf<D>(half), std::move(mesh));
    std::size_t found = 0;
    long long queries = 0;
    const double deepest = deepestPhi<D>(bar, lower, upper, &found, &queries);
    const double h = 2.0 * L / n;
    if (found == 0) {
      std::printf("| %d | %zu | %.6g | %lld | 0 | none | %.6f (all of it) | %.6f |\n", n, count,
                  h, queries, -exact, slope * h / 2.0);
    } else {
      std::printf("| %d | %zu | %.6g | %lld | %zu | %.6f | %.6f | %.6f |\n", n, count, h,
                  queries, found, deepest, deepest - exact, slope * h / 2.0);
    }
  }
  // The error depends on where the crossing falls between samples: over 100 random
  // crossings (xi, eta) in [-0.4, 0.4]^2 it fills the band up to the bound.
  std::printf("\nOver 100 random crossing points (xi, eta) in [-0.4, 0.4]^2:\n\n");
  std::printf("| n | spacing h | crossings missed | mean error | max error | bound |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const int n : {1, 2, 4, 8, 16, 32, 64, 128}) {
    const AnalyticShape<D, BoxSdf<D>> bar(BoxSdf<D>(half), barMesh<D>(half, n));
    Uniform uniform{2024};
    int missed = 0;
    double sum = 0.0, worst = 0.0;
    for (int trial = 0; trial < 100; ++trial) {
      const double x = uniform(-0.4, 0.4), y = uniform(-0.4, 0.4);
      placeBars<D>(x, y, lower, upper);
      const double error = deepestPhi<D>(bar, lower, upper, nullptr, nullptr) - exact;
      missed += error == -exact ? 1 : 0;
      sum += error;
      worst = std::max(worst, error);
    }
    const double h = 2.0 * L / n;
    std::printf("| %d | %.6g | %d | %.6f | %.6f | %.6f |\n", n, h, missed, sum / 100.0, worst,
                std::min(slope * h / 2.0, -exact));
  }
  std::printf("\n");
}

}  // namespace

int main() {
  table<3>();
  table<2>();
}
