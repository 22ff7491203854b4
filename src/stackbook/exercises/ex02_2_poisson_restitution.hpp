#pragma once
/// \file
/// \brief Exercise 2.2: Poisson restitution, a coefficient on the impulse rather than on the
/// velocity (chapter 2, "Exercises").

#include "stackbook/impulse/frictionless_impulse.hpp"

namespace stackbook::exercises {

/// A frictionless impact split into its two phases.
template <int D>
struct PoissonImpulse {
  double compression = 0.0;   ///< normal impulse of the compression phase: it ends when u_n = 0
  double restitution = 0.0;   ///< normal impulse of the restitution phase: e_P * compression
  Vec<D> j = Vec<D>::Zero();  ///< the whole impulse, (compression + restitution) n
};

/// Poisson's law for a frictionless impact with coefficient e_P in [0, 1]. The compression
/// impulse is the normal impulse that brings the normal relative velocity to zero (Eq. (2.2)
/// with u_n' = 0); the restitution impulse is e_P times it; j is their sum along n.
/// Separating or resting contacts (u_n >= 0) and immovable pairs
/// (n^T K n <= immovableTolerance * trace(K)) get the zero result.
/// Throws std::invalid_argument when e_P is not in [0, 1].
template <int D>
PoissonImpulse<D> poissonImpulse(const Mat<D>& K, const Vec<D>& u, const Vec<D>& n, double eP,
                                 double immovableTolerance = kDefaultImmovableTolerance);

}  // namespace stackbook::exercises
