#pragma once
// Seeded random bodies, poses and contacts for property tests (pbrt-style loops).
// std::mt19937_64 with a fixed seed: the same sequence on every run.

#include <cmath>
#include <random>

#include "stackbook/body/rigid_body.hpp"

namespace stackbook::testing {

class RandomSource {
 public:
  explicit RandomSource(std::uint64_t seed) : engine_(seed) {}

  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }

  /// Log-uniform in [lo, hi]: spreads samples over orders of magnitude.
  double logUniform(double lo, double hi) {
    return std::exp(uniform(std::log(lo), std::log(hi)));
  }

  template <int D>
  Vec<D> vector(double lo, double hi) {
    Vec<D> v;
    for (int i = 0; i < D; ++i) v[i] = uniform(lo, hi);
    return v;
  }

  template <int D>
  Vec<D> unitVector() {
    for (;;) {
      const Vec<D> v = vector<D>(-1.0, 1.0);
      const double n = v.norm();
      if (n > 0.1 && n <= 1.0) return v / n;
    }
  }

  template <int D>
  AngVec<D> angularVector(double lo, double hi) {
    AngVec<D> w;
    for (int i = 0; i < kAngularDim<D>; ++i) w[i] = uniform(lo, hi);
    return w;
  }

  template <int D>
  Orientation<D> orientation() {
    if constexpr (D == 2) {
      return Eigen::Rotation2Dd(uniform(-M_PI, M_PI));
    } else {
      for (;;) {
        // One draw per statement: the order in which a call's arguments are evaluated is
        // unspecified (gcc goes right to left, clang left to right), and the stream must be
        // the same whichever compiler builds the tests. z is drawn first, as gcc did.
        const double z = uniform(-1, 1), y = uniform(-1, 1), x = uniform(-1, 1), w = uniform(-1, 1);
        const Eigen::Quaterniond q(w, x, y, z);
        if (q.norm() >= 0.1) return q.normalized();
      }
    }
  }

  /// Physically valid principal moments for mass m: those of a box with random sides.
  template <int D>
  AngVec<D> principalInertia(double mass, double minSide = 0.1, double maxSide = 2.0) {
    if constexpr (D == 2) {
      const double a = uniform(minSide, maxSide), b = uniform(minSide, maxSide);
      AngVec<2> I;
      I << mass * (a * a + b * b) / 12.0;
      return I;
    } else {
      const double a = uniform(minSide, maxSide), b = uniform(minSide, maxSide),
                   c = uniform(minSide, maxSide);
      return AngVec<3>(mass * (b * b + c * c) / 12.0, mass * (a * a + c * c) / 12.0,
                       mass * (a * a + b * b) / 12.0);
    }
  }

  /// A dynamic body with random mass, inertia, pose and velocities.
  template <int D>
  RigidBody<D> dynamicBody(double minMass = 0.1, double maxMass = 10.0) {
    const double m = logUniform(minMass, maxMass);
    RigidBody<D> body = makeDynamicBody<D>(m, principalInertia<D>(m));
    body.position = vector<D>(-3.0, 3.0);
    body.orientation = orientation<D>();
    body.velocity = vector<D>(-2.0, 2.0);
    body.setAngularVelocity(angularVector<D>(-3.0, 3.0));
    return body;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace stackbook::testing
