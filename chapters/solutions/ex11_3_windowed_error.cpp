// Exercise 11.3, reference solution: see ex11_3_windowed_error.hpp and chapter 11.
#include <cmath>
#include <stdexcept>

#include "stackbook/exercises/ex11_3_windowed_error.hpp"

namespace stackbook {

double windowedError(const Integrator& step, const State1& start, int windows, double window, double coarseDt,
                     double fineDt) {
  if (windows < 1 || !(window > 0.0) || !(fineDt > 0.0) || !(fineDt < coarseDt)) {
    throw std::invalid_argument("windowedError: need windows >= 1, window > 0 and 0 < fineDt < coarseDt");
  }
  State1 fine = start;
  double sum = 0.0;
  for (int w = 0; w < windows; ++w) {
    const State1 coarseEnd = step(fine, window, coarseDt);
    const State1 fineEnd = step(fine, window, fineDt);
    sum += std::abs(coarseEnd.x - fineEnd.x);
    fine = fineEnd;  // the next window restarts from the fine run
  }
  return sum / windows;
}

}  // namespace stackbook
