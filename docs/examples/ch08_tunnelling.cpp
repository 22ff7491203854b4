// Chapter 8, validation case B18: how fast can a ball hit a thin plate before it tunnels?
// A ball of radius 0.1 (icosphere samples in 3D, 48-gon in 2D) falls without gravity onto
// a static plate 0.02 thick, at a spot where no plate sample lies under it, starting at 8
// phases of one step's travel; e = 0.5, so a clean bounce keeps KE'/KE = e^2 = 0.25.
// Printed as Markdown for the course page (\include{doc} ch08_tunnelling.out).
#include <algorithm>
#include <cstdio>

#include "../../tests/ch08/plate_scene.hpp"  // the scene of the B18 tests: testing::plateRun

using namespace stackbook;
using stackbook::testing::PlateRun;
using stackbook::testing::plateRun;

namespace {

template <int D>
void table(double dt) {
  for (const double speed : {5.0, 9.5, 10.5, 20.0, 40.0, 80.0, 160.0, 320.0}) {
    int tunnelled = 0, finite = 0;
    double maxRatio = 0.0;
    const int phases = 8;
    for (int p = 0; p < phases; ++p) {
      const PlateRun o = plateRun<D>(speed, static_cast<double>(p) / phases, dt);
      tunnelled += o.tunnelled ? 1 : 0;
      finite += o.finite ? 1 : 0;
      maxRatio = std::max(maxRatio, o.energyRatio);
    }
    std::printf("| %dD | %g | %.3f | %d of %d | %d of %d | %.3f |\n", D, speed, speed * dt / 0.02,
                tunnelled, phases, finite, phases, maxRatio);
  }
}

}  // namespace

int main() {
  std::printf("| dimension | v (m/s) | v dt / h | tunnelled | finite | largest KE'/KE |\n"
              "|---|---|---|---|---|---|\n");
  table<2>(1e-3);
  table<3>(1e-3);
}
