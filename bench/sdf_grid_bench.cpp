// Benchmark (not a test) for chapter 6: what a signed-distance grid costs and how accurate
// it is, for the bundled shapes at several resolutions.
//
//   cmake --preset release && cmake --build --preset release --target sdf_grid_bench
//   ./build/release/bench/sdf_grid_bench [max cells, default 128] [repeats, default 3]
//
// The course page shows the same table up to 64 cells: docs/examples/ch06_costs.cpp
// includes this file with STACKBOOK_BENCH_NO_MAIN defined and calls runSdfGridBench.
//
// For each shape and resolution n (cells across the largest extent) it prints, as a
// Markdown table:
//   nodes, memory      the grid's size (8 bytes per node)
//   build ms           building from the mesh (distances by the face hierarchy, sign by
//                      winding number per region); the best of `repeats` runs up to 64
//                      cells, one run above
//   winding sums       points where the full winding number was summed
//   phi ns, phi+N ns   cost of one query at points near the surface (best of `repeats`
//                      passes of 20 queries per point)
//   grid error         max and RMS |grid - exact distance to the mesh|: the grid's error
//   total error        max and RMS |grid - analytic distance| where the shape has one:
//                      grid error plus the mesh's tessellation error
// Points: 2000 per shape, uniform in the mesh's box grown by 1 % of its largest extent
// (inside the grid up to 256 cells, whose 3 cells of padding are 1.2 % of it), kept where
// |phi| <= 5 % of that extent. Times are the CPU time of the running thread
// (clock_gettime with CLOCK_THREAD_CPUTIME_ID), so that other programs sharing the machine
// do not inflate them; they are still those of whatever machine runs the benchmark.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "stackbook/geometry/analytic_sdf.hpp"
#include "stackbook/geometry/mesh_nonconvex.hpp"
#include "stackbook/geometry/sdf_grid.hpp"

using namespace stackbook;

namespace {

/// CPU seconds used by this thread so far.
double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

template <int D>
struct BenchShape {
  std::string name;
  SurfaceMesh<D> mesh;
  std::function<double(const Vec<D>&)> analytic;  // empty when there is no closed form
};

volatile double sink = 0.0;  // keeps the query loops from being optimised away

/// 0.0123 as "1.2e-2": two significant digits, short enough for a table cell.
std::string compact(double x) {
  if (x == 0.0) return "0";
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(x))));
  char text[32];
  std::snprintf(text, sizeof text, "%.1fe%d", x / std::pow(10.0, exponent), exponent);
  return text;
}

template <int D>
void benchShape(const BenchShape<D>& shape, const std::vector<int>& resolutions, int repeats) {
  const ExactMeshSdf<D> exact(shape.mesh);
  const Aabb<D> bounds = shape.mesh.bounds();
  const double size = bounds.extent().maxCoeff();
  const std::function<double(const Vec<D>&)> exactPhi = [&](const Vec<D>& x) {
    return exact.distance(x);
  };
  const std::vector<Vec<D>> points =
      sampleBand<D>(exactPhi, bounds.inflated(0.01 * size), -0.05 * size, 0.05 * size, 2000, 11);
  std::vector<double> reference(points.size()), analytic(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    reference[i] = exact.distance(points[i]);
    if (shape.analytic) analytic[i] = shape.analytic(points[i]);
  }
  for (const int n : resolutions) {
    SdfGridSettings settings;
    settings.cellsAcrossLargestExtent = n;
    double buildSeconds = 1e300;
    SdfGrid<D> grid;
    const int builds = n <= 64 ? repeats : 1;
    for (int run = 0; run < builds; ++run) {
      const double start = threadSeconds();
      grid = buildSdfGrid<D>(shape.mesh, settings, shape.name);
      buildSeconds = std::min(buildSeconds, threadSeconds() - start);
    }
    const double queries = 20.0 * static_cast<double>(points.size());
    double phiNs = 1e300, bothNs = 1e300;
    for (int pass = 0; pass < repeats; ++pass) {
      double start = threadSeconds();
      double sum = 0.0;
      for (int r = 0; r < 20; ++r) {
        for (const Vec<D>& x : points) sum += grid.value(x);
      }
      phiNs = std::min(phiNs, 1e9 * (threadSeconds() - start) / queries);
      start = threadSeconds();
      for (int r = 0; r < 20; ++r) {
        for (const Vec<D>& x : points) sum += grid.value(x) + grid.normal(x)[0];
      }
      bothNs = std::min(bothNs, 1e9 * (threadSeconds() - start) / queries);
      sink = sink + sum;
    }
    double gridMax = 0.0, gridSq = 0.0, totalMax = 0.0, totalSq = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double phi = grid.value(points[i]);
      const double e = std::abs(phi - reference[i]);
      gridMax = std::max(gridMax, e);
      gridSq += e * e;
      if (shape.analytic) {
        const double t = std::abs(phi - analytic[i]);
        totalMax = std::max(totalMax, t);
        totalSq += t * t;
      }
    }
    const double count = double(points.size());
    std::printf("| %dD %s | %zu | %d | %lld | %.1f | %.1f | %lld | %.0f | %.0f | %s, %s |", D,
                shape.name.c_str(), shape.mesh.faces.size(), n,
                static_cast<long long>(grid.nodeCount()),
                static_cast<double>(grid.memoryBytes()) / 1048576.0, 1e3 * buildSeconds,
                static_cast<long long>(grid.stats().windingEvaluations), phiNs, bothNs,
                compact(gridMax).c_str(), compact(std::sqrt(gridSq / count)).c_str());
    if (shape.analytic) {
      std::printf(" %s, %s |\n", compact(totalMax).c_str(), compact(std::sqrt(totalSq / count)).c_str());
    } else {
      std::printf(" - |\n");
    }
    std::fflush(stdout);
  }
}

/// Prints the benchmark table for resolutions 16, 32, ... up to maxCells (2D: one more).
void runSdfGridBench(int maxCells, int repeats) {
  std::vector<int> resolutions;
  for (int n = 16; n <= maxCells; n *= 2) resolutions.push_back(n);

  std::printf("| shape | faces | cells | nodes | MiB | build ms | winding sums | phi ns | "
              "phi+N ns | grid error max, RMS | total error max, RMS |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");

  const SphereSdf<3> sphere(0.5);
  const BoxSdf<3> box(Vec3(0.5, 0.3, 0.2));
  const TorusSdf<3> torus(0.5, 0.2);
  const std::vector<BenchShape<3>> shapes3 = {
      {"box", boxMesh(Vec3(1.0, 0.6, 0.4), 4), [&](const Vec3& x) { return box.distance(x); }},
      {"sphere", icosphereMesh(0.5, 3), [&](const Vec3& x) { return sphere.distance(x); }},
      {"torus", torusMesh(0.5, 0.2, 48, 24), [&](const Vec3& x) { return torus.distance(x); }},
      {"L-block", lShapeBoundary<3>(0.5, 4), {}},
      {"cup", cupBoundary<3>(), {}},
      {"bone", boneBoundary<3>(), {}},
  };
  for (const BenchShape<3>& shape : shapes3) benchShape<3>(shape, resolutions, repeats);

  const SphereSdf<2> disk(0.5);
  const std::vector<BenchShape<2>> shapes2 = {
      {"disk", regularPolygon(0.5, 64), [&](const Vec2& x) { return disk.distance(x); }},
      {"L", lShapeBoundary<2>(0.5, 4), {}},
      {"U", uPolygon(), {}},
      {"star", starPolygon(), {}},
  };
  std::vector<int> resolutions2 = resolutions;
  resolutions2.push_back(2 * resolutions.back());
  for (const BenchShape<2>& shape : shapes2) benchShape<2>(shape, resolutions2, repeats);
}

}  // namespace

#ifndef STACKBOOK_BENCH_NO_MAIN
int main(int argc, char** argv) {
  const int maxCells = argc > 1 ? std::atoi(argv[1]) : 128;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  runSdfGridBench(maxCells, std::max(1, repeats));
  return 0;
}
#endif
