#pragma once
/// \file
/// \brief What one pair visit leaves of a sample's approach (chapter 9, Eq. (9.10)): the
/// arithmetic behind the contact ramp under long and short pair loops.

#include <cmath>

namespace stackbook {

// [visit_leaves]
/// The fraction of a sample's approach speed that one pair visit leaves when every impulse
/// of the visit acts at that sample with restitution `e` in [-1, 0] (Eq. (9.10)). Impulse i
/// leaves -e of what approached before it, so (-e)^i after i impulses, and is (-e)^(i-1)
/// times the visit's first in size. The visit ends at `cap` impulses, at separation (e = 0
/// leaves nothing to find again), or after impulse i > 1 when (-e)^(i-1) <= `tolerance`, the
/// loop tolerance of chapter 8 (0: off). GBF's loop is cap 20 without a tolerance.
inline double pairVisitLeaves(double e, int cap, double tolerance) {
  double left = 1.0;
  for (int i = 1; i <= cap; ++i) {
    const double size = left;  // impulse i over impulse 1: (-e)^(i-1), what approached before it
    left *= std::abs(e);       // e <= 0: the impulse leaves -e of what approached
    if (left == 0.0) break;    // separated: the sample is not found again
    if (i > 1 && tolerance > 0.0 && size <= tolerance) break;
  }
  return left;
}
// [visit_leaves]

}  // namespace stackbook
