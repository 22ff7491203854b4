// Exercise 12.2, reference solution: the critical offset of a leaning tower (chapter 12).
#include "stackbook/exercises/ex12_2_critical_offset.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace stackbook {

double criticalOffset(int n) {
  if (n < 2) throw std::invalid_argument("criticalOffset: a tower needs n >= 2 boxes, got " + std::to_string(n));
  // Box j (1-based) sits at x_j = s (j - 1). While every box carries, each load enters at the
  // centre of load above it, so the centre of load of boxes j..n is their mean, s (j - 1) + s (n - j) / 2.
  // Box j >= 2 rests on a patch ending at box j - 1's edge, s (j - 2) + 1/2: s (n - j + 2) / 2 <= 1/2.
  // Box 1 rests on the ground's patch ending at 1/2: s (n - 1) / 2 <= 1/2.
  double bound = 1.0 / static_cast<double>(n - 1);
  for (int j = 2; j <= n; ++j) bound = std::min(bound, 1.0 / static_cast<double>(n - j + 2));
  return bound;  // 1 / n: box 2 under the n - 1 boxes above it binds first
}

}  // namespace stackbook
