#pragma once
/// \file
/// \brief Exercise 8.3 (\ref ch08): the steepest slope on which rolling friction holds a
/// ball at rest.
///
/// A ball (or disk) of radius R rests on a slope of angle theta with friction enough to
/// stick. About the contact point gravity has the moment m g R sin(theta); rolling
/// friction can oppose it with a couple of at most mu_r times the normal force
/// m g cos(theta) (Eq. (8.7) per step). Return the largest theta at which the ball stays,
/// in radians. Throw std::invalid_argument for mu_r < 0 or R <= 0. The tests then check that
/// the step holds a ball just below that angle and lets it roll just above.

namespace stackbook::exercises {

/// The largest slope angle (radians) on which a ball of the given radius stays at rest
/// under rolling friction with coefficient `rollingFriction` (a length).
double rollingRestAngle(double rollingFriction, double radius);

}  // namespace stackbook::exercises
