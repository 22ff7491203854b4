#pragma once
/// \file
/// \brief Exercise 11.1 (\ref ch11_exercises): the observed order of convergence of a
/// knob's curve, the slope that says whether an error is first order in dt (the step's
/// Euler parts) or second (the implicit midpoint rule).

#include <vector>

namespace stackbook {

/// For knob values h_0 > h_1 > ... (e.g. time steps) with errors e_k, the observed orders
/// p_k = log(e_k / e_{k+1}) / log(h_k / h_{k+1}), one per consecutive pair (size n - 1).
/// Throws std::invalid_argument when the sizes differ, fewer than two points are given, or
/// a value or an error is not finite and > 0, or two knob values are equal.
std::vector<double> observedOrders(const std::vector<double>& knob, const std::vector<double>& error);

}  // namespace stackbook
