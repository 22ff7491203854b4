#pragma once
/// \file
/// \brief Exercise 8.1 (\ref ch08): a CFL rule that chooses the time step from the
/// tunnelling limit of Eq. (8.9).
///
/// A sample that first reaches into a plate of thickness h at depth d is turned back only
/// if d < h / 2 (beyond, the bottom face is nearer and the normal points the wrong way).
/// In one step a body falling at speed v under gravity g travels at most
/// v dt + g dt^2 (the collision stage's prediction, Eq. (8.1)). Return the largest dt with
///
///     v dt + g dt^2 <= safety * h / 2,
///
/// the positive root of a quadratic; compute it in a form that does not cancel when
/// g dt^2 is tiny against v dt. With v = g = 0 any step is safe: return +infinity.
/// Throw std::invalid_argument for v < 0, g < 0, h <= 0 or safety outside (0, 1].

namespace stackbook::exercises {

/// The largest time step for which a body at speed `speed` under gravity `gravity` cannot
/// pass the middle of a feature `thickness` thick in one step, with the margin `safety`.
double cflTimeStep(double speed, double gravity, double thickness, double safety = 1.0);

}  // namespace stackbook::exercises
