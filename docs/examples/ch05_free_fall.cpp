// Chapter 5: free fall under the semi-implicit Euler step against the continuum solution,
// printed as a Markdown table for the course page (\include{doc} ch05_free_fall.out).
// A body starts at height 10 m with velocity (1.5, 2) m/s, g = 9.81 m/s^2, and falls for 1 s.
#include <cmath>
#include <cstdio>

#include "stackbook/body/integrate.hpp"

int main() {
  using namespace stackbook;
  const Vec2 x0(0.0, 10.0), v0(1.5, 2.0), g(0.0, -9.81);
  const double T = 1.0;
  const Vec2 exact = x0 + T * v0 + 0.5 * T * T * g;
  std::printf("The continuum height after 1 s is %.6f m.\n\n", exact.y());
  std::printf("| dt (s) | steps | height after 1 s (m) | error vs continuum (m) | error ratio | "
              "g dt T / 2 (m) |\n|---|---|---|---|---|---|\n");
  double previous = 0.0;
  for (const double dt : {1e-2, 5e-3, 2.5e-3, 1.25e-3}) {
    RigidBody<2> body = makeDynamicBody<2>(1.0, AngVec<2>::Constant(1.0));
    body.position = x0;
    body.velocity = v0;
    const int n = static_cast<int>(std::lround(T / dt));
    for (int step = 0; step < n; ++step) advanceFreeBody<2>(body, dt, gravityLoads<2>(g));
    const double error = (body.position - exact).norm();
    if (previous > 0.0) {
      std::printf("| %g | %d | %.9f | %.4e | %.6f | %.4e |\n", dt, n, body.position.y(), error,
                  previous / error, 0.5 * g.norm() * dt * T);
    } else {
      std::printf("| %g | %d | %.9f | %.4e | | %.4e |\n", dt, n, body.position.y(), error,
                  0.5 * g.norm() * dt * T);
    }
    previous = error;
  }
}
