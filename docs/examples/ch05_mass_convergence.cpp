// Chapter 5: mass properties of refined meshes against the smooth solids they approximate,
// and what the apex of the signed simplices does far from the origin. Printed as Markdown
// (\include{doc} ch05_mass_convergence.out).
#include <cmath>
#include <cstdio>

#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/mesh_primitives.hpp"

using namespace stackbook;

int main() {
  std::printf("**Icosphere of radius 1** against the ball (V = 4 pi / 3, I = 2 m r^2 / 5); errors are 1 - mesh / ball.\n\n"
              "| level | triangles | volume error | ratio | moment error | ratio |\n"
              "|---|---|---|---|---|---|\n");
  double pv = 0.0, pi = 0.0;
  for (int level = 0; level <= 6; ++level) {
    const TriangleMesh mesh = icosphereMesh(1.0, level);
    const MassProperties<3> p = computeMassProperties<3>(mesh);
    const double ev = 1.0 - p.measure / (4.0 * M_PI / 3.0), ei = 1.0 - p.inertia(0, 0) / (0.4 * p.mass);
    if (level > 0) {
      std::printf("| %d | %zu | %.4e | %.3f | %.4e | %.3f |\n", level, mesh.faces.size(), ev, pv / ev, ei, pi / ei);
    } else {
      std::printf("| %d | %zu | %.4e | | %.4e | |\n", level, mesh.faces.size(), ev, ei);
    }
    pv = ev;
    pi = ei;
  }

  const double R = 1.0, r = 0.3, V = 2.0 * M_PI * M_PI * R * r * r;
  std::printf("\n**Torus R = 1, r = 0.3** with N segments around the axis and N/2 around the tube "
              "(V = 2 pi^2 R r^2, axial m(R^2 + 3r^2/4), transverse m(R^2/2 + 5r^2/8)); errors are 1 - mesh / torus.\n\n"
              "| N | volume error | axial moment error | transverse moment error | "
              "volume against Eq. (5.24) |\n|---|---|---|---|---|\n");
  for (int N = 8; N <= 256; N *= 2) {
    const MassProperties<3> p = computeMassProperties<3>(torusMesh(R, r, N, N / 2));
    const int M = N / 2;
    const double pappus = N * std::sin(2.0 * M_PI / N) / (2.0 * M_PI) * 2.0 * M_PI * R *
                          (0.5 * M * r * r * std::sin(2.0 * M_PI / M));
    std::printf("| %d | %.4e | %.4e | %.4e | %.1e |\n", N, 1.0 - p.measure / V,
                1.0 - p.inertia(2, 2) / (p.mass * (R * R + 0.75 * r * r)),
                1.0 - p.inertia(0, 0) / (p.mass * (0.5 * R * R + 0.625 * r * r)), p.measure / pappus - 1.0);
  }

  std::printf("\n**Regular N-gon of circumradius 1** against the unit disk (area pi, J = m r^2 / 2); errors are 1 - polygon / disk.\n\n"
              "| N | area error | polar moment error |\n|---|---|---|\n");
  for (int N = 8; N <= 1024; N *= 4) {
    const MassProperties<2> p = computeMassProperties<2>(regularPolygon(1.0, N));
    std::printf("| %d | %.4e | %.4e |\n", N, 1.0 - p.measure / M_PI, 1.0 - p.inertia(0, 0) / (0.5 * p.mass));
  }

  std::printf("\n**A 1 x 2 x 3 box moved away from the origin** by d (1, 0.7, -0.3): largest "
              "error of the inertia tensor relative to its largest moment.\n\n"
              "| d (m) | apex at the origin | apex at the bounds centre (default) |\n|---|---|---|\n");
  const Vec3 size(1.0, 2.0, 3.0);
  const Vec3 exact = Vec3(4.0 + 9.0, 1.0 + 9.0, 1.0 + 4.0) * (6.0 / 12.0);
  for (const double d : {0.0, 1e2, 1e3, 1e4, 1e5, 1e6}) {
    TriangleMesh mesh = boxMesh(size);
    for (Vec3& p : mesh.vertices) p += d * Vec3(1.0, 0.7, -0.3);
    MassPropertySettings origin;
    origin.apexAtBoundsCenter = false;
    const Mat3 naive = computeMassProperties<3>(mesh, 1.0, origin).inertia;
    const Mat3 centred = computeMassProperties<3>(mesh).inertia;
    const Mat3 reference = exact.asDiagonal();
    std::printf("| %g | %.1e | %.1e |\n", d, (naive - reference).cwiseAbs().maxCoeff() / exact.maxCoeff(),
                (centred - reference).cwiseAbs().maxCoeff() / exact.maxCoeff());
  }
}
