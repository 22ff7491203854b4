#pragma once
/// \file
/// \brief Exercise 11.3 (\ref ch11_exercises): the self-consistency error of Erez, Tassa
/// and Todorov (ICRA 2015): a coarse run against a much finer one over short windows, each
/// window restarted from the fine run's state, so that chaos is not counted as error.

#include <functional>
#include <vector>

namespace stackbook {

/// One state of a scalar system (position x and velocity v).
struct State1 {
  double x = 0.0;
  double v = 0.0;
};

/// Advances a state by `duration` seconds with the time step `dt`.
using Integrator = std::function<State1(const State1& start, double duration, double dt)>;

/// The mean over `windows` windows of length `window` of |x_coarse - x_fine| at the end of the
/// window, both runs started at the window from the fine run's state there: window w starts
/// at t = w * window from the fine state reached from `start`. Throws std::invalid_argument
/// unless windows >= 1, window > 0 and 0 < fineDt < coarseDt.
double windowedError(const Integrator& step, const State1& start, int windows, double window, double coarseDt,
                     double fineDt);

}  // namespace stackbook
