#pragma once
/// \file
/// \brief Exercise 1.1: the effective mass of a contact along a direction, and the
/// directions in which it is lightest and heaviest (\ref ch01).

#include "stackbook/math/types.hpp"

namespace stackbook {

/// The effective mass of the collision matrix K along the direction d:
/// m_eff = 1 / (d^T K d) with d normalised. It is the mass of the free particle that,
/// pushed along d, changes its velocity along d as the contact point does.
/// K must be symmetric positive semidefinite and d nonzero. Returns +infinity when
/// d^T K d = 0 (no impulse along d can change the velocity along d: two static bodies).
template <int D>
double effectiveMass(const Mat<D>& K, const Vec<D>& d);

/// The extremes of effectiveMass(K, d) over all directions d.
template <int D>
struct EffectiveMassExtremes {
  double lightest = 0.0;                       ///< smallest effective mass
  Vec<D> lightestDirection = Vec<D>::Zero();   ///< a unit direction where it is reached
  double heaviest = 0.0;                       ///< largest effective mass (may be +infinity)
  Vec<D> heaviestDirection = Vec<D>::Zero();   ///< a unit direction where it is reached
};

/// The lightest and heaviest effective masses of the symmetric positive semidefinite K and
/// unit directions that reach them. Hint: the Rayleigh quotient d^T K d / d^T d.
template <int D>
EffectiveMassExtremes<D> effectiveMassExtremes(const Mat<D>& K);

}  // namespace stackbook
