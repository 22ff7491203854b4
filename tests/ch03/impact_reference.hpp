#pragma once
// The impact integrated through time (Routh's method), as a reference for the one-shot
// impulse of chapter 3. During a collision the velocity changes with the normal impulse p
// as du/dp = K (n + f), where f is the friction per unit normal impulse: f = -mu s/|s|
// while the contact slips with velocity s = u_t, and any |f| <= mu that keeps s = 0 while it
// sticks. The impact ends when u_n = -e u_n(0) (Newton's restitution, as in Eq. (3.1)).
//
// In 2D each phase has a constant f, so u is piecewise linear in p and integrateImpact2D
// is exact. In 3D the slip direction turns during a phase; integrateImpact3D follows it
// with small steps (a measuring tool for the docs, accurate to about 1e-4).

#include <cmath>

#include "stackbook/math/types.hpp"

namespace stackbook::testing {

/// What happened to the slip during an integrated impact.
enum class SlipHistory {
  Slid,          ///< slipped from start to end (or started at rest and slid)
  Stuck,         ///< ended stuck (u_t' = 0)
  Reversed,      ///< slip stopped, then slid the other way
  Jammed,        ///< u_n stopped rising (Painleve): no finite impact
};

template <int D>
struct IntegratedImpact {
  Vec<D> j = Vec<D>::Zero();
  SlipHistory history = SlipHistory::Slid;
};

/// Exact planar impact with Coulomb friction and Newton restitution (see above).
/// A slip below 1e-14 |u| at the start counts as none.
inline IntegratedImpact<2> integrateImpact2D(const Mat2& K, Vec2 u, const Vec2& n, double e,
                                             double mu) {
  IntegratedImpact<2> result;
  const Vec2 t(-n.y(), n.x());
  const double target = -e * u.dot(n);
  double slip = u.dot(t);
  if (std::abs(slip) <= 1e-14 * u.norm()) slip = 0.0;
  bool stopped = false;
  for (int phase = 0; phase < 3; ++phase) {
    double f;  // friction along t per unit normal impulse, constant in this phase
    if (slip != 0.0) {
      f = slip > 0.0 ? -mu : mu;
    } else {
      const double hold = -t.dot(K * n) / t.dot(K * t);  // keeps d(slip)/dp = 0
      if (std::abs(hold) <= mu) {
        f = hold;
        result.history = SlipHistory::Stuck;
      } else {
        f = t.dot(K * n) > 0.0 ? -mu : mu;  // slides the way K n pushes it
        if (stopped) result.history = SlipHistory::Reversed;
      }
    }
    const Vec2 rate = K * Vec2(n + f * t);  // du/dp
    const double unRate = rate.dot(n);
    if (!(unRate > 0.0)) {
      result.history = SlipHistory::Jammed;
      return result;
    }
    const double pEnd = (target - u.dot(n)) / unRate;
    const double slipRate = rate.dot(t);
    if (slip != 0.0 && slip * slipRate < 0.0 && -slip / slipRate < pEnd) {
      const double pStop = -slip / slipRate;  // the slip stops before the impact ends
      result.j += pStop * Vec2(n + f * t);
      u += pStop * rate;
      slip = 0.0;
      stopped = true;
      continue;
    }
    result.j += pEnd * Vec2(n + f * t);
    return result;
  }
  return result;
}

/// The planar impact stepped in 3D: follows the turning slip direction with steps of
/// at most 1/steps of the frictionless normal impulse, and shorter ones near a stop.
inline IntegratedImpact<3> integrateImpact3D(const Mat3& K, Vec3 u, const Vec3& n, double e,
                                             double mu, int steps = 4000) {
  IntegratedImpact<3> result;
  const double un0 = u.dot(n);
  const double target = -e * un0;
  const double dpMax = -(1.0 + e) * un0 / n.dot(K * n) / steps;
  const double scale = u.norm();
  // An orthonormal tangent basis (t1, t2).
  const Vec3 seed = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = (seed - seed.dot(n) * n).normalized();
  const Vec3 t2 = n.cross(t1);
  bool stopped = false;
  for (int iteration = 0; iteration < 100 * steps; ++iteration) {
    Vec3 s = u - u.dot(n) * n;
    Vec3 f;
    if (s.norm() > 1e-10 * scale) {
      f = -mu * s.normalized();
    } else {
      // Stuck: the friction that keeps s = 0 solves the tangential 2 x 2 block.
      Eigen::Matrix2d Ktt;
      Ktt << t1.dot(K * t1), t1.dot(K * t2), t2.dot(K * t1), t2.dot(K * t2);
      const Eigen::Vector2d Ktn(t1.dot(K * n), t2.dot(K * n));
      const Eigen::Vector2d hold = -Ktt.inverse() * Ktn;
      if (hold.norm() <= mu) {
        f = hold.x() * t1 + hold.y() * t2;
        result.history = SlipHistory::Stuck;
      } else {
        // Slides off in the direction d whose slip rate (K (n - mu d))_t is along +d.
        double best = -2.0;
        Vec3 d = t1;
        for (int k = 0; k < 3600; ++k) {
          const double phi = 2.0 * M_PI * k / 3600.0;
          const Vec3 c = std::cos(phi) * t1 + std::sin(phi) * t2;
          const Vec3 w = K * Vec3(n - mu * c);
          const Vec3 wt = w - w.dot(n) * n;
          const double align = wt.dot(c) / wt.norm();
          if (align > best) {
            best = align;
            d = c;
          }
        }
        f = -mu * d;
        if (stopped) result.history = SlipHistory::Reversed;
      }
    }
    const Vec3 rate = K * Vec3(n + f);
    const double unRate = rate.dot(n);
    if (!(unRate > 0.0)) {
      result.history = SlipHistory::Jammed;
      return result;
    }
    double dp = dpMax;
    const Vec3 sRate = rate - unRate * n;
    const bool sliding = s.norm() > 1e-10 * scale;
    if (sliding && sRate.norm() > 0.0) dp = std::min(dp, 0.02 * s.norm() / sRate.norm());
    bool last = false;
    if (u.dot(n) + dp * unRate >= target) {
      dp = (target - u.dot(n)) / unRate;
      last = true;
    }
    if (sliding && s.dot(sRate) < 0.0) {
      const double pStop = -s.dot(sRate) / sRate.squaredNorm();  // closest approach to s = 0
      const Vec3 sAtStop = s + pStop * sRate;
      if (pStop <= dp && sAtStop.norm() <= 1e-3 * s.norm()) {
        dp = pStop;
        last = false;
        result.j += dp * Vec3(n + f);
        u += dp * rate;
        u = u.dot(n) * n;  // snap the slip to zero
        stopped = true;
        continue;
      }
    }
    result.j += dp * Vec3(n + f);
    u += dp * rate;
    if (last) return result;
  }
  return result;
}

}  // namespace stackbook::testing
