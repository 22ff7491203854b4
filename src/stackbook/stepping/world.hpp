#pragma once
/// \file
/// \brief The scene a time step advances (chapter 8): rigid bodies, their shapes, their
/// materials and gravity, with the rule that combines two materials into the restitution
/// and friction of a contact, and the checks that reject a malformed scene.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/rigid_body.hpp"
#include "stackbook/collision/candidate_list_store.hpp"
#include "stackbook/geometry/shape.hpp"

namespace stackbook {

// [material]
/// What a body's surface does in a contact (chapter 8).
struct Material {
  /// Coefficient of restitution e in [0, 1] for the collision stage: 0 stops the normal
  /// approach, 1 reverses it. (The contact stage ignores it and uses its own schedule.)
  double restitution = 0.0;
  /// Coulomb friction coefficient mu >= 0 (static and kinetic alike, as in GBF).
  double friction = 0.0;
  /// Rolling-friction coefficient mu_r >= 0, a length in metres (0 by default: off). After a
  /// sticking impulse with normal part j_n, the couple (angular impulse) that brakes the
  /// pair's relative rolling is at most mu_r j_n, and likewise the couple that brakes
  /// spinning (Eq. (8.7)): the classical rolling-resistance law, torque <= mu_r times the
  /// normal force, integrated over the impulse. A ball of radius R rolling on level
  /// ground then decelerates at mu_r g / (R (1 + I / (m R^2))) (Eq. (8.8)).
  double rollingFriction = 0.0;
};
// [material]

// [pair_material]
/// The coefficients of one contact between two materials.
struct PairMaterial {
  double restitution = 0.0;  ///< e of the pair
  double friction = 0.0;     ///< mu of the pair
  double rollingFriction = 0.0;  ///< rolling coefficient of the pair (a length)
};

/// The pair rule: e = min(e_1, e_2), mu = min(mu_1, mu_2), and likewise for the rolling
/// coefficient (Eq. (8.4)). The less elastic and the
/// less rough surface decides, which is PhysBAM's rule for e. It is symmetric, keeps
/// e in [0, 1], and a frictionless (mu = 0) or perfectly plastic (e = 0) surface stays so
/// whatever it touches. Other rules (geometric mean for mu, as several engines use) are
/// equally defensible; what matters is that the rule is symmetric and stated.
inline PairMaterial combineMaterials(const Material& a, const Material& b) {
  return PairMaterial{std::min(a.restitution, b.restitution), std::min(a.friction, b.friction),
                      std::min(a.rollingFriction, b.rollingFriction)};  // Eq. (8.4)
}
// [pair_material]

// [world]
/// A scene: body i is bodies[i] with shape shapes[i] and material materials[i], all in
/// the world frame, under the uniform gravity `gravity` (an acceleration: every dynamic
/// body receives dt g per step, static bodies none). Shapes are shared and immutable, so
/// a hundred equal boxes hold one shape. Build it with addBody() and check it with
/// validateWorld(); the step functions validate it on entry.
template <int D>
struct World {
  std::vector<RigidBody<D>> bodies;
  std::vector<std::shared_ptr<const Shape<D>>> shapes;
  std::vector<Material> materials;
  Vec<D> gravity = Vec<D>::Zero();
  /// Sleeping (chapter 8, "Sleeping"): per body, how long it has been at rest (s) and
  /// whether it sleeps. Empty until a step with sleeping on sizes them; a step without
  /// sleeping ignores them.
  std::vector<double> restTime;
  std::vector<char> asleep;
  /// Candidate lists (chapter 7, "Keeping lists between stages") that the impulse stages and
  /// the shock-propagation pass hand on to the next stage and the next step. They change how
  /// much work a query does, never its answer; empty until a step with candidate lists.
  CandidateListStore<D> candidateLists;

  /// Append a body and return its index.
  int addBody(const RigidBody<D>& body, std::shared_ptr<const Shape<D>> shape,
              const Material& material = {}) {
    bodies.push_back(body);
    shapes.push_back(std::move(shape));
    materials.push_back(material);
    return static_cast<int>(bodies.size()) - 1;
  }

  /// Number of bodies.
  int size() const { return static_cast<int>(bodies.size()); }

  /// The loads on body i during one step: gravity only (a static body ignores them).
  ExternalLoads<D> loads(int /*i*/) const { return gravityLoads<D>(gravity); }

  /// The coefficients of a contact between bodies i and k (combineMaterials()).
  PairMaterial pairMaterial(int i, int k) const {
    return combineMaterials(materials.at(static_cast<std::size_t>(i)),
                            materials.at(static_cast<std::size_t>(k)));
  }
};
// [world]

namespace detail {

template <int D>
bool orientationFinite(const Orientation<D>& q) {
  if constexpr (D == 2) {
    return std::isfinite(q.angle());
  } else {
    return q.coeffs().allFinite() && q.norm() > 0.0;
  }
}

[[noreturn]] inline void throwBadBody(const char* caller, std::size_t i, const std::string& what) {
  std::ostringstream msg;
  msg << caller << ": body " << i << ": " << what;
  throw std::invalid_argument(msg.str());
}

}  // namespace detail

// [validate_world]
/// Throws std::invalid_argument unless the scene is well formed. The message names the
/// function, the body index and the field, e.g. "validateWorld: body 3: material.friction
/// (mu) must be finite and >= 0, got -0.2". Checked: the three arrays have one entry per
/// body; every shape is set; position, orientation (a non-zero quaternion in 3D),
/// velocity and angular momentum are finite; 1/m and 1/I are finite and >= 0; e in
/// [0, 1]; mu and the rolling coefficient finite and >= 0; gravity finite.
template <int D>
void validateWorld(const World<D>& world, const char* caller = "validateWorld") {
  if (world.shapes.size() != world.bodies.size() || world.materials.size() != world.bodies.size()) {
    std::ostringstream msg;
    msg << caller << ": the world has " << world.bodies.size() << " bodies but "
        << world.shapes.size() << " shapes and " << world.materials.size()
        << " materials; use addBody() to keep them in step";
    throw std::invalid_argument(msg.str());
  }
  if (!world.gravity.allFinite()) {
    std::ostringstream msg;
    msg << caller << ": gravity must be finite, got (" << world.gravity.transpose() << ")";
    throw std::invalid_argument(msg.str());
  }
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody<D>& b = world.bodies[i];
    const Material& m = world.materials[i];
    // The same checks as below without building a message: a step validates every body,
    // and a string stream per body was a measurable share of a large scene's step.
    if (world.shapes[i] != nullptr && b.position.allFinite() && detail::orientationFinite<D>(b.orientation) &&
        b.velocity.allFinite() && b.angularMomentum.allFinite() && std::isfinite(b.inverseMass) &&
        b.inverseMass >= 0.0 && b.inverseInertia.allFinite() && !(b.inverseInertia.array() < 0.0).any() &&
        m.restitution >= 0.0 && m.restitution <= 1.0 && std::isfinite(m.friction) && m.friction >= 0.0 &&
        std::isfinite(m.rollingFriction) && m.rollingFriction >= 0.0) {
      continue;
    }
    std::ostringstream got;
    if (world.shapes[i] == nullptr) detail::throwBadBody(caller, i, "shape is null");
    if (!b.position.allFinite()) {
      got << "position must be finite, got (" << b.position.transpose() << ")";
    } else if (!detail::orientationFinite<D>(b.orientation)) {
      got << "orientation must be finite (and a non-zero quaternion in 3D)";
    } else if (!b.velocity.allFinite()) {
      got << "velocity must be finite, got (" << b.velocity.transpose() << ")";
    } else if (!b.angularMomentum.allFinite()) {
      got << "angularMomentum must be finite, got (" << b.angularMomentum.transpose() << ")";
    } else if (!std::isfinite(b.inverseMass) || b.inverseMass < 0.0) {
      got << "inverseMass must be finite and >= 0, got " << b.inverseMass;
    } else if (!b.inverseInertia.allFinite() || (b.inverseInertia.array() < 0.0).any()) {
      got << "inverseInertia must be finite and >= 0, got (" << b.inverseInertia.transpose() << ")";
    } else if (!(m.restitution >= 0.0 && m.restitution <= 1.0)) {
      got << "material.restitution (e) must be in [0, 1], got " << m.restitution;
    } else if (!(std::isfinite(m.friction) && m.friction >= 0.0)) {
      got << "material.friction (mu) must be finite and >= 0, got " << m.friction;
    } else if (!(std::isfinite(m.rollingFriction) && m.rollingFriction >= 0.0)) {
      got << "material.rollingFriction must be finite and >= 0, got " << m.rollingFriction;
    }
    if (!got.str().empty()) detail::throwBadBody(caller, i, got.str());
  }
}
// [validate_world]

}  // namespace stackbook
