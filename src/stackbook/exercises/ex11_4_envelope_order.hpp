#pragma once
/// \file
/// \brief Exercise 11.4 (\ref ch11_exercises): the order of a curve that scatters, such as a
/// symmetric structure's drift or a bounce's apexes (\ref ch11_stack_shapes), read from its
/// upper envelope.

#include <vector>

namespace stackbook {

/// The indices of the upper envelope of a curve's points (dt[k], error[k]): the points that no
/// point at a smaller or equal time step beats with a larger error, in the order given.
/// Throws std::invalid_argument if the sizes differ, there are fewer than two points, a time
/// step is not > 0, two time steps are equal, or an error is not > 0.
std::vector<std::size_t> upperEnvelope(const std::vector<double>& dt, const std::vector<double>& error);

/// The envelope's order: the least-squares slope of log(error) against log(dt) over the
/// upper envelope's points (Eq. (11.2) with the time step for the cost). Throws
/// std::invalid_argument as upperEnvelope() does, and if the envelope has fewer than two points.
double envelopeOrder(const std::vector<double>& dt, const std::vector<double>& error);

}  // namespace stackbook
