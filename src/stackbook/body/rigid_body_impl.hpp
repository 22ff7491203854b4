#pragma once
// Implementation of validateMassProperties and makeDynamicBody (declared in rigid_body.hpp).

#include <sstream>

namespace stackbook {

// [make_dynamic_body]
template <int D>
void validateMassProperties(const char* context, double mass, const AngVec<D>& principalInertia) {
  if (!std::isfinite(mass) || !(mass > 0.0)) {
    std::ostringstream msg;
    msg << context << ": mass must be finite and positive, got " << mass;
    throw std::invalid_argument(msg.str());
  }
  for (int k = 0; k < kAngularDim<D>; ++k) {
    const double I = principalInertia[k];
    if (!std::isfinite(I) || !(I > 0.0)) {
      std::ostringstream msg;
      msg << context << ": principal moment of inertia " << k
          << " must be finite and positive, got " << I;
      throw std::invalid_argument(msg.str());
    }
  }
  if constexpr (D == 3) {
    const double A = principalInertia[0], B = principalInertia[1], C = principalInertia[2];
    // A physical mass distribution has each moment at most the sum of the other two:
    // I_x + I_y - I_z = 2 sum m z^2 >= 0 (chapter 1, "World-frame inertia").
    const double slack = 1e-12 * (A + B + C);
    if (A + B < C - slack || B + C < A - slack || C + A < B - slack) {
      std::ostringstream msg;
      msg << context << ": principal moments (" << A << ", " << B << ", " << C
          << ") violate the triangle inequality (each must be at most the sum of the other two)";
      throw std::invalid_argument(msg.str());
    }
  }
}

template <int D>
RigidBody<D> makeDynamicBody(double mass, const AngVec<D>& principalInertia) {
  validateMassProperties<D>("makeDynamicBody", mass, principalInertia);
  RigidBody<D> body;
  body.inverseMass = 1.0 / mass;
  body.inertia = principalInertia;
  body.inverseInertia = principalInertia.cwiseInverse();
  return body;
}
// [make_dynamic_body]

}  // namespace stackbook
