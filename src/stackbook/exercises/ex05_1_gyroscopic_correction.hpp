#pragma once
/// \file
/// \brief Exercise 5.1: the gyroscopic correction of the orientation update (chapter 5,
/// "Exercises").

#include "stackbook/body/integrate.hpp"

namespace stackbook::exercises {

/// The position update of Eqs. (5.8)-(5.12) with PhysBAM's gyroscopic correction: the
/// orientation turns by the exponential map with
///
///     w = omega - (dt/2) I_world^{-1} (omega x L)
///
/// instead of omega, the first-order estimate of the angular velocity at the middle of the
/// step (omega changes as dω/dt = -I_world^{-1}(omega x L) when L is fixed, Eq. (5.6)).
/// Otherwise as advancePosition: x += dt v, then omega is re-derived from the unchanged L.
/// In 2D omega and L are parallel, omega x L = 0 and the update is advancePosition's.
/// A static body is handled as in advancePosition.
template <int D>
void advancePositionGyroscopic(RigidBody<D>& body, double dt);

/// One free step with the corrected position update: advanceVelocity, then
/// advancePositionGyroscopic.
template <int D>
void advanceFreeBodyGyroscopic(RigidBody<D>& body, double dt,
                               const ExternalLoads<D>& loads = ExternalLoads<D>{});

}  // namespace stackbook::exercises
