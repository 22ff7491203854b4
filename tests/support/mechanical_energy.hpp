#pragma once
// Kinetic plus potential energy of a world's dynamic bodies, for the tests' "no energy
// gain" checks (one definition for every test file of a unity build).
#include "stackbook/stepping/world.hpp"

namespace stackbook::testing {

/// Kinetic plus potential energy of the world's dynamic bodies (gravity along -up);
/// bodies with zero inverse mass carry none.
template <int D>
double mechanicalEnergy(const World<D>& world) {
  double e = 0.0;
  for (const RigidBody<D>& b : world.bodies) {
    if (b.inverseMass == 0.0) continue;
    e += b.kineticEnergy() - b.mass() * world.gravity.dot(b.position);
  }
  return e;
}

}  // namespace stackbook::testing
