// Exercise 11.2, reference solution: see ex11_2_apex_heights.hpp and chapter 11.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stackbook/exercises/ex11_2_apex_heights.hpp"

namespace stackbook {

std::vector<double> apexHeights(const std::vector<double>& heights) {
  std::vector<double> apexes;
  for (std::size_t k = 1; k + 1 < heights.size(); ++k) {
    if (heights[k] > heights[k - 1] && heights[k] > heights[k + 1]) apexes.push_back(heights[k]);
  }
  return apexes;
}

double apexError(const std::vector<double>& heights, double h0, double e, int count) {
  if (!(h0 > 0.0)) throw std::invalid_argument("apexError: h0 must be > 0");
  const std::vector<double> apexes = apexHeights(heights);
  if (static_cast<int>(apexes.size()) < count) throw std::invalid_argument("apexError: too few apexes");
  double worst = 0.0;
  for (int k = 1; k <= count; ++k) {
    const double expected = std::pow(e, 2.0 * k) * h0;  // v' = e v, so h' = e^2 h
    worst = std::max(worst, std::abs(apexes[static_cast<std::size_t>(k - 1)] / expected - 1.0));
  }
  return worst;
}

}  // namespace stackbook
