// Exercise 1.1 (your answer goes here): see ex01_1_effective_mass.hpp and chapter 1.
// Implement: effectiveMass and effectiveMassExtremes. Delete every TODO(reader) comment once
// your code is in: while one is left, the exercise counts as not solved and its tests do not
// run.
#include "stackbook/exercises/ex01_1_effective_mass.hpp"

namespace stackbook {

template <int D>
double effectiveMass(const Mat<D>& K, const Vec<D>& d) {
  // TODO(reader): return 1 / (d^T K d) for the normalised d (+infinity when it is 0).
  (void)K;
  (void)d;
  return 0.0;
}

template <int D>
EffectiveMassExtremes<D> effectiveMassExtremes(const Mat<D>& K) {
  // TODO(reader): find the lightest and heaviest effective masses and their directions.
  (void)K;
  return {};
}

template double effectiveMass<2>(const Mat<2>&, const Vec<2>&);
template double effectiveMass<3>(const Mat<3>&, const Vec<3>&);
template EffectiveMassExtremes<2> effectiveMassExtremes<2>(const Mat<2>&);
template EffectiveMassExtremes<3> effectiveMassExtremes<3>(const Mat<3>&);

}  // namespace stackbook
