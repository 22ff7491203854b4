// Chapter 6: the signed-distance grid: interpolation, sign, convergence, normals, the
// region outside the grid, and the Shape built on it.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/sdf_grid.hpp"
#include "support/dimensions.hpp"
#include "support/eigen_checks.hpp"
#include "support/random_bodies.hpp"
#include "geometry_helpers.hpp"

using namespace stackbook;
using stackbook::testing::at;
using stackbook::testing::In2D;
using stackbook::testing::In3D;
using stackbook::testing::RandomSource;

namespace {


template <int D>
Vec<D> randomIn(RandomSource& random, const Aabb<D>& box) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = random.uniform(box.lower[k], box.upper[k]);
  return x;
}

// The largest angle between the normals of two triangles that share an edge.
double largestDihedralBend(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, std::vector<Vec3>> normals;
  for (const auto& f : mesh.faces) {
    const Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                       .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                       .normalized();
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      normals[{std::min(a, b), std::max(a, b)}].push_back(n);
    }
  }
  double worst = 0.0;
  for (const auto& [edge, n] : normals) {
    worst = std::max(worst, std::atan2(n[0].cross(n[1]).norm(), n[0].dot(n[1])));
  }
  return worst;
}

// Observed order of convergence between two resolutions whose cell sizes differ by 2.
double order(double coarse, double fine) { return std::log2(coarse / fine); }

// Errors of the grid sampled from an analytic SDF, against that SDF, at band points that
// lie inside the region (so inside every grid, away from its one-sided edge nodes).
template <int D, class Sdf>
SdfErrorStats analyticGridError(const Sdf& sdf, const std::vector<Vec<D>>& points, int cells,
                                SdfGradientMethod gradient) {
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = cells;
  settings.gradient = gradient;
  const std::function<double(const Vec<D>&)> phi = [&](const Vec<D>& x) { return sdf.distance(x); };
  const SdfGrid<D> grid = sampleSdfGrid<D>(phi, sdf.bounds(), settings);
  return compareSdf<D>(
      points, [&](const Vec<D>& x) { return grid.value(x); },
      [&](const Vec<D>& x) { return grid.normal(x); }, phi,
      [&](const Vec<D>& x) { return sdf.normal(x); });
}

template <int D, class Sdf>
std::vector<Vec<D>> bandPoints(const Sdf& sdf, double lo, double hi, int count, std::uint64_t seed) {
  const std::function<double(const Vec<D>&)> phi = [&](const Vec<D>& x) { return sdf.distance(x); };
  return sampleBand<D>(phi, sdf.bounds(), lo, hi, count, seed);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [test_multilinear_exact]
TEST_CASE_TEMPLATE("multilinear interpolation reproduces multilinear functions exactly", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  // phi = 0.3 + 0.7 x - 0.2 y + 0.5 x y (+ 0.4 z - 0.3 x z + 0.2 y z + 0.6 x y z): linear in
  // each coordinate, so Eq. (6.11) reproduces it and Eq. (6.13, left) its gradient.
  const auto f = [](const Vec<D>& p) {
    double v = 0.3 + 0.7 * p[0] - 0.2 * p[1] + 0.5 * p[0] * p[1];
    if constexpr (D == 3) v += 0.4 * p[2] - 0.3 * p[0] * p[2] + 0.2 * p[1] * p[2] + 0.6 * p[0] * p[1] * p[2];
    return v;
  };
  const auto gradient = [](const Vec<D>& p) {
    Vec<D> g;
    g[0] = 0.7 + 0.5 * p[1];
    g[1] = -0.2 + 0.5 * p[0];
    if constexpr (D == 3) {
      g[0] += -0.3 * p[2] + 0.6 * p[1] * p[2];
      g[1] += 0.2 * p[2] + 0.6 * p[0] * p[2];
      g[2] = 0.4 - 0.3 * p[0] + 0.2 * p[1] + 0.6 * p[0] * p[1];
    }
    return g;
  };
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 7;
  settings.gradient = SdfGradientMethod::InterpolantDerivative;
  const Aabb<D> region{Vec<D>::Constant(-1.0), Vec<D>::Constant(1.0)};
  const SdfGrid<D> grid = sampleSdfGrid<D>(f, region, settings);
  RandomSource random(81);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec<D> x = randomIn<D>(random, grid.box());
    CHECK(grid.value(x) == doctest::Approx(f(x)).epsilon(1e-13));
    CHECK_EIGEN_NEAR(grid.gradient(x), gradient(x), 1e-12, 1e-12);
  }
  // Central differences are exact for a linear function, one-sided ones at the edge too.
  const auto linear = [](const Vec<D>& p) { return 0.3 + 0.7 * p[0] - 0.2 * p[1] + 0.4 * p[D - 1]; };
  Vec<D> slope = Vec<D>::Zero();
  slope[0] = 0.7;
  slope[1] = -0.2;
  slope[D - 1] += 0.4;
  settings.gradient = SdfGradientMethod::CentralDifferences;
  const SdfGrid<D> plane = sampleSdfGrid<D>(linear, region, settings);
  for (int trial = 0; trial < 100; ++trial) {
    CHECK_EIGEN_NEAR(plane.gradient(randomIn<D>(random, plane.box())), slope, 1e-12, 1e-12);
  }
}
// [test_multilinear_exact]

TEST_CASE("the grid layout has the requested resolution and padding") {
  const TriangleMesh box = boxMesh(Vec3(1.0, 0.6, 0.4));
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 20;
  const SdfGrid<3> grid = buildSdfGrid<3>(box, settings, "box");
  CHECK(grid.cellSize() == doctest::Approx(0.05).epsilon(1e-15));
  // Cells: ceil(extent / h) + 2 x 3 padding; nodes: one more.
  CHECK(grid.nodeCounts() == std::array<int, 3>{27, 19, 15});
  CHECK(grid.memoryBytes() == 27u * 19u * 15u * sizeof(double));
  const Aabb<3> inner = grid.box().inflated(-3.0 * 0.05 + 1e-12);
  CHECK(inner.contains(box.bounds().lower));
  CHECK(inner.contains(box.bounds().upper));
  settings.cellSize = 0.1;  // overrides the cell count
  CHECK(buildSdfGrid<3>(box, settings, "box").nodeCounts() == std::array<int, 3>{17, 13, 11});
}

TEST_CASE_TEMPLATE("the sign by region equals the sign by winding number at every node", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  const int cells = D == 3 ? 8 : 40;
  const SurfaceMesh<D> meshes[] = {cupBoundary<D>({}, 16, 0.1), ringBoundary<D>(0.5, 0.2, 16, 8),
                                   boneBoundary<D>({}, 16, 0.1), lShapeBoundary<D>(0.5, 2)};
  for (const SurfaceMesh<D>& mesh : meshes) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    settings.paddingCells = 1;  // the per-node reference costs nodes x faces
    const SdfGrid<D> regions = buildSdfGrid<D>(mesh, settings);
    settings.sign = SdfSignMethod::WindingNumberPerNode;
    const SdfGrid<D> perNode = buildSdfGrid<D>(mesh, settings);
    CHECK(regions.values() == perNode.values());
    // Far fewer winding sums: the surface-free links join all but a band of nodes.
    CHECK(regions.stats().windingEvaluations * 4 < perNode.stats().windingEvaluations);
    CHECK(regions.stats().maxWindingDeviation < 1e-12);
  }
}

// [test_grid_sign]
TEST_CASE_TEMPLATE("the grid puts the cup cavity and the ring hole outside", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = D == 3 ? 16 : 48;
  const GridShape<D> cup(cupBoundary<D>({}, 24), "cup", settings);
  const double h = cup.grid().cellSize();
  // Cavity centre (on the axis, 0.2 above the box centre), middle of the wall, bottom:
  // outside, inside, inside.
  CHECK(cup.signedDistance(at<D>(0.0, 0.2)) > 0.0);
  CHECK(cup.signedDistance(at<D>(0.45, 0.0)) < 0.0);
  CHECK(cup.signedDistance(at<D>(0.0, -0.35)) < 0.0);
  // The cavity centre is 0.4 from the inner wall (3D: from the inscribed 24-gon, whose
  // inradius is 0.4 cos(pi/24)). It lies on the cavity's medial axis, where the grid
  // error can reach sqrt(D) h / 2 (Eq. (6.12)).
  const double cavity = D == 3 ? 0.4 * std::cos(M_PI / 24) : 0.4;
  CHECK(std::abs(cup.signedDistance(at<D>(0.0, 0.2)) - cavity) <= 0.5 * std::sqrt(D) * h);

  const GridShape<D> ring(ringBoundary<D>(0.5, 0.2), "ring", settings);
  CHECK(ring.signedDistance(Vec<D>::Zero()) > 0.0);   // the hole
  CHECK(ring.signedDistance(at<D>(0.5, 0.0)) < 0.0);  // the tube's core
  CHECK(ring.signedDistance(at<D>(2.0, 1.0)) > 0.0);  // far outside the grid
}
// [test_grid_sign]

TEST_CASE_TEMPLATE("grid node values are the exact signed distances to the mesh", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const SurfaceMesh<D> bone = boneBoundary<D>({}, 16, 0.08);
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = D == 3 ? 8 : 32;
  const SdfGrid<D> grid = buildSdfGrid<D>(bone, settings);
  const ExactMeshSdf<D> exact(bone);
  RandomSource random(82);
  for (int trial = 0; trial < 60; ++trial) {
    std::array<int, D> node;
    for (int k = 0; k < D; ++k) {
      node[k] = static_cast<int>(random.uniform(0, grid.nodeCounts()[k] - 1e-9));
    }
    CHECK(grid.nodeValue(node) == doctest::Approx(exact.distance(grid.nodePosition(node))).epsilon(1e-13));
  }
  // Between nodes: phi is 1-Lipschitz, so the interpolant is within
  // h sqrt(sum_k t_k (1 - t_k)) <= sqrt(D) h / 2 of it (Eq. (6.12)) whatever the kinks.
  const double h = grid.cellSize();
  for (int trial = 0; trial < 200; ++trial) {
    const Vec<D> x = randomIn<D>(random, grid.box());
    double spread = 0.0;
    for (int k = 0; k < D; ++k) {
      const double s = (x[k] - grid.box().lower[k]) / h;
      const double t = s - std::floor(s);
      spread += t * (1.0 - t);
    }
    CHECK(std::abs(grid.value(x) - exact.distance(x)) <= h * std::sqrt(spread) * (1 + 1e-12) + 1e-15);
  }
}

// [test_grid_eikonal]
TEST_CASE_TEMPLATE("the grid gradient has unit length away from the medial axis", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Band: 0.3 <= |x| <= 0.55 around a sphere (disk) of radius 0.5, at least 4.8 cells from
  // the centre, the medial axis, where grad phi has no limit. For the exact sphere, central
  // differences at a node are short by (h^2 / 2 rho^2)(1 - 1/D) at most, and interpolating
  // unit vectors that turn by h/rho per cell shortens them by D h^2 / (8 rho^2): together
  // | |grad phi| - 1 | <= c_D h^2 / rho^2, c_2 = 1/2, c_3 = 17/24.
  const double rhoMin = 0.3, rhoMax = 0.55;
  const double c = D == 3 ? 17.0 / 24.0 : 0.5;
  const SphereSdf<D> sphere(0.5);
  const std::function<double(const Vec<D>&)> phi = [&](const Vec<D>& x) { return sphere.distance(x); };
  // A mesh adds kinks where face normals turn by up to theta (the largest dihedral bend):
  // mixing components of two unit normals moves the length by at most theta.
  SurfaceMesh<D> mesh;
  double theta = 0.0;
  if constexpr (D == 3) {
    mesh = icosphereMesh(0.5, 2);
    theta = largestDihedralBend(mesh);
  } else {
    mesh = regularPolygon(0.5, 64);
    theta = 2.0 * M_PI / 64;
  }
  RandomSource random(83);
  for (const int cells : {16, 32}) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = cells;
    const SdfGrid<D> exactGrid = sampleSdfGrid<D>(phi, sphere.bounds(), settings);
    const SdfGrid<D> meshGrid = buildSdfGrid<D>(mesh, settings);
    const double h = exactGrid.cellSize();
    double worstExact = 0.0, worstMesh = 0.0;
    for (int trial = 0; trial < 400;) {
      const Vec<D> x = random.vector<D>(-rhoMax, rhoMax);
      if (x.norm() < rhoMin || x.norm() > rhoMax) continue;
      ++trial;
      worstExact = std::max(worstExact, std::abs(exactGrid.gradient(x).norm() - 1.0));
      worstMesh = std::max(worstMesh, std::abs(meshGrid.gradient(x).norm() - 1.0));
    }
    CAPTURE(cells);
    CAPTURE(worstExact);
    CAPTURE(worstMesh);
    CHECK(worstExact <= c * h * h / (rhoMin * rhoMin));
    CHECK(worstMesh <= c * h * h / (rhoMin * rhoMin) + theta);
  }
}
// [test_grid_eikonal]

// [test_grid_convergence]
TEST_CASE_TEMPLATE("interpolation error falls as h squared for smooth shapes", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Grids sampled from the exact sphere and torus (no tessellation error): the error is
  // the interpolation error alone, O(h^2) by Eq. (6.12) in a band that avoids the medial
  // axis. Central-difference normals converge at O(h^2) too, the interpolant's gradient
  // only at O(h). Observed orders from 16 to 64 cells (two halvings of h).
  const SphereSdf<D> sphere(0.5);
  const TorusSdf<D> torus(0.5, 0.2);
  const std::vector<Vec<D>> spherePoints = bandPoints<D>(sphere, -0.25, 0.25, 800, 84);
  const std::vector<Vec<D>> torusPoints = bandPoints<D>(torus, -0.1, 0.1, 800, 85);
  for (int shape = 0; shape < 2; ++shape) {
    CAPTURE(shape);
    SdfErrorStats cd[2], id[2];
    for (int level = 0; level < 2; ++level) {
      const int cells = level == 0 ? 16 : 64;
      if (shape == 0) {
        cd[level] = analyticGridError<D>(sphere, spherePoints, cells, SdfGradientMethod::CentralDifferences);
        id[level] = analyticGridError<D>(sphere, spherePoints, cells, SdfGradientMethod::InterpolantDerivative);
      } else {
        cd[level] = analyticGridError<D>(torus, torusPoints, cells, SdfGradientMethod::CentralDifferences);
        id[level] = analyticGridError<D>(torus, torusPoints, cells, SdfGradientMethod::InterpolantDerivative);
      }
    }
    const double valueOrder = 0.5 * order(cd[0].maxError, cd[1].maxError);
    const double rmsOrder = 0.5 * order(cd[0].rmsError, cd[1].rmsError);
    const double cdNormalOrder = 0.5 * order(cd[0].maxAngle, cd[1].maxAngle);
    const double idNormalOrder = 0.5 * order(id[0].maxAngle, id[1].maxAngle);
    CAPTURE(valueOrder);
    CAPTURE(rmsOrder);
    CAPTURE(cdNormalOrder);
    CAPTURE(idNormalOrder);
    CHECK(valueOrder > 1.8);
    CHECK(valueOrder < 2.2);
    CHECK(rmsOrder > 1.8);
    CHECK(rmsOrder < 2.2);
    CHECK(cdNormalOrder > 1.5);
    CHECK(cdNormalOrder < 2.5);
    CHECK(idNormalOrder > 0.8);
    CHECK(idNormalOrder < 1.3);
  }
}
// [test_grid_convergence]

TEST_CASE_TEMPLATE("interpolation error is first order across the kinks of a box", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // Inside a box phi = -min over faces: its gradient jumps on the medial planes that run
  // from the edges to the centre. A cell cut by such a plane keeps an error of order
  // h |jump of grad phi|, so the maximum error is a fixed fraction of h, not O(h^2):
  // for min(x, y) bilinear interpolation leaves h/4, for min(x, y, z) 0.385 h.
  Vec<D> half = Vec<D>::Constant(0.2);
  half[0] = 0.5;
  half[1] = 0.3;
  const BoxSdf<D> box(half);
  const std::vector<Vec<D>> points = bandPoints<D>(box, -1.0, 0.02, 2000, 86);
  for (const int cells : {16, 32, 64}) {
    const SdfErrorStats e = analyticGridError<D>(box, points, cells, SdfGradientMethod::CentralDifferences);
    const double h = 1.0 / cells;
    CAPTURE(cells);
    CHECK(e.maxError > 0.1 * h);
    CHECK(e.maxError < 0.6 * h);
  }
}

// [test_tessellation_gap]
TEST_CASE_TEMPLATE("the grid of a tessellated sphere stays within the tessellation gap", Dim, In2D,
                   In3D) {
  constexpr int D = Dim::value;
  // Mesh M inscribed in the sphere S of radius R, with gap H = max distance between them
  // (R minus the smallest distance from the centre to a face's plane). For every point,
  // |phi_M - phi_S| <= H, so every node of M's grid is within H of the sphere's distance,
  // and between nodes grid_M - phi_S = I[phi_M - phi_S] + (I[phi_S] - phi_S): the gap plus
  // the interpolation error of the exact sphere on the same nodes.
  const double R = 0.5;
  SurfaceMesh<D> mesh;
  if constexpr (D == 3) {
    mesh = icosphereMesh(R, 2);
  } else {
    mesh = regularPolygon(R, 24);
  }
  double H = 0.0;
  for (const auto& f : mesh.faces) {
    const Vec<D> a = mesh.vertices[f[0]], b = mesh.vertices[f[1]];
    double planeDistance = 0.0;
    if constexpr (D == 3) {
      const Vec3 c = mesh.vertices[f[2]];
      planeDistance = std::abs(a.dot((b - a).cross(c - a).normalized()));
    } else {
      planeDistance = std::abs(a.x() * b.y() - a.y() * b.x()) / (b - a).norm();
    }
    H = std::max(H, R - planeDistance);
  }
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = D == 3 ? 16 : 64;
  const SdfGrid<D> grid = buildSdfGrid<D>(mesh, settings);
  const SphereSdf<D> sphere(R);
  for (std::int64_t i = 0; i < grid.nodeCount(); ++i) {
    std::array<int, D> node;
    std::int64_t rest = i;
    for (int k = 0; k < D; ++k) {
      node[k] = static_cast<int>(rest % grid.nodeCounts()[k]);
      rest /= grid.nodeCounts()[k];
    }
    REQUIRE(std::abs(grid.nodeValue(node) - sphere.distance(grid.nodePosition(node))) <= H * (1 + 1e-12));
  }
  const std::function<double(const Vec<D>&)> phi = [&](const Vec<D>& x) { return sphere.distance(x); };
  const SdfGrid<D> exactGrid = sampleSdfGrid<D>(phi, mesh.bounds(), settings);  // same nodes
  RandomSource random(87);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec<D> x = randomIn<D>(random, grid.box());
    const double interpolation = std::abs(exactGrid.value(x) - phi(x));
    CHECK(std::abs(grid.value(x) - phi(x)) <= H + interpolation + 1e-12);
  }
}
// [test_tessellation_gap]

// [test_grid_outside]
TEST_CASE_TEMPLATE("outside the grid phi grows with the distance and the normal points away",
                   Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  SurfaceMesh<D> mesh;
  if constexpr (D == 3) {
    mesh = icosphereMesh(0.5, 2);
  } else {
    mesh = regularPolygon(0.5, 32);
  }
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 16;
  const SdfGrid<D> grid = buildSdfGrid<D>(mesh, settings);
  const ExactMeshSdf<D> exact(mesh);
  RandomSource random(88);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec<D> x = random.vector<D>(-4.0, 4.0);
    if (grid.box().contains(x)) continue;
    const Vec<D> p = x.cwiseMax(grid.box().lower).cwiseMin(grid.box().upper);
    // Eq. (6.14): the value at the box plus the distance to the box.
    CHECK(grid.value(x) == doctest::Approx(grid.value(p) + (x - p).norm()).epsilon(1e-14));
    // phi is 1-Lipschitz, so phi(p) + |x - p| >= phi(x): never an underestimate beyond
    // the grid's own error at p (less than 0.01 here).
    CHECK(grid.value(x) >= exact.distance(x) - 0.01);
    // The normal has a positive component along x - p: it points away from the grid box.
    CHECK(grid.normal(x).dot(x - p) > 0.0);
    CHECK(grid.normal(x).norm() == doctest::Approx(1.0).epsilon(1e-14));
  }
  // Continuous across the box boundary: just outside equals just inside plus the step.
  Vec<D> onFace = Vec<D>::Zero();
  onFace[0] = grid.box().upper[0];
  Vec<D> step = Vec<D>::Zero();
  step[0] = 1e-9;
  CHECK(std::abs(grid.value(onFace + step) - grid.value(onFace - step)) < 3e-9);
}
// [test_grid_outside]

TEST_CASE_TEMPLATE("a grid shape samples its mesh vertices and rejects bad meshes by name", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = D == 3 ? 12 : 40;
  const GridShape<D> ell(lShapeBoundary<D>(0.5, 2), "L", settings);
  CHECK(ell.surfaceSamples().size() == ell.mesh().vertices.size());
  CHECK(ell.describe().rfind("L (grid", 0) == 0);
  const double h = ell.grid().cellSize();
  // The grid is exact at nodes and the L's corners sit on nodes or between them; on the
  // surface phi interpolates the kink of the L's edges, error below h/2.
  for (const Vec<D>& p : ell.surfaceSamples()) CHECK(std::abs(ell.signedDistance(p)) < 0.5 * h);
  CHECK(ell.bounds().contains(ell.surfaceSamples().front()));

  SurfaceMesh<D> open = lShapeBoundary<D>(0.5, 1);
  open.faces.pop_back();
  CHECK_THROWS_WITH_AS(GridShape<D>(open, "broken L", settings),
                       doctest::Contains("broken L: invalid"), MeshError);
}

TEST_CASE("grid settings are checked by name") {
  const TriangleMesh box = boxMesh(Vec3(1, 1, 1));
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 1;
  CHECK_THROWS_WITH_AS(buildSdfGrid<3>(box, settings), doctest::Contains("cellsAcrossLargestExtent"),
                       std::invalid_argument);
  settings = {};
  settings.paddingCells = 0;
  CHECK_THROWS_WITH_AS(buildSdfGrid<3>(box, settings), doctest::Contains("paddingCells"),
                       std::invalid_argument);
  settings = {};
  settings.cellsAcrossLargestExtent = 1000;
  settings.maxNodes = 1'000'000;
  CHECK_THROWS_WITH_AS(buildSdfGrid<3>(box, settings), doctest::Contains("maxNodes"),
                       std::invalid_argument);
}

// [test_written_out_gradient]
TEST_CASE_TEMPLATE("the written-out central-difference gradient has the bits of the corner loop", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  // A wavy function, so that no node difference is special; a grid small enough that many
  // points fall in edge cells, where the differences are one-sided.
  const std::function<double(const Vec<D>&)> wavy = [](const Vec<D>& p) {
    double v = p.norm() - 0.6;
    for (int k = 0; k < D; ++k) v += 0.05 * std::sin(7.0 * p[k] + k);
    return v;
  };
  SdfGridSettings settings;
  settings.cellsAcrossLargestExtent = 6;
  settings.gradient = SdfGradientMethod::CentralDifferences;
  const SdfGrid<D> grid = sampleSdfGrid<D>(wavy, Aabb<D>{Vec<D>::Constant(-1.0), Vec<D>::Constant(1.0)}, settings);
  const auto sameBits = [](const Vec<D>& a, const Vec<D>& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * D) == 0;
  };
  RandomSource random(83);
  const Aabb<D>& box = grid.box();
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Vec<D> x = randomIn<D>(random, box);
    // Every fourth point on a node plane or a face of the box, where a corner or a cell edge
    // is hit exactly.
    if (trial % 4 == 1) x[trial % D] = grid.nodePosition(typename SdfGrid<D>::Index{})[trial % D] + grid.cellSize() * (trial % 7);
    if (trial % 4 == 2) x[trial % D] = (trial % 8 < 4) ? box.lower[trial % D] : box.upper[trial % D];
    x = x.cwiseMax(box.lower).cwiseMin(box.upper);
    const Vec<D> loop = grid.gradientByCorners(x, SdfGradientMethod::CentralDifferences);
    CHECK(sameBits(grid.gradient(x), loop));
    ++checked;
  }
  CHECK(checked == 3000);
  // The other method is the loop itself.
  settings.gradient = SdfGradientMethod::InterpolantDerivative;
  const SdfGrid<D> other = sampleSdfGrid<D>(wavy, Aabb<D>{Vec<D>::Constant(-1.0), Vec<D>::Constant(1.0)}, settings);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec<D> x = randomIn<D>(random, other.box());
    CHECK(sameBits(other.gradient(x), other.gradientByCorners(x, SdfGradientMethod::InterpolantDerivative)));
  }
}
// [test_written_out_gradient]

}  // TEST_SUITE
