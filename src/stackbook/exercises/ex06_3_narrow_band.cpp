// Exercise 6.3 (your answer goes here): see ex06_3_narrow_band.hpp and chapter 6.
// Implement: NarrowBandGrid (its constructor, value, storedNodes and memoryBytes).
// Delete every TODO(reader) comment once your code is in: while one is left, the exercise
// counts as not solved and its tests do not run.
#include "stackbook/exercises/ex06_3_narrow_band.hpp"

namespace stackbook::exercises {

template <int D>
struct NarrowBandGrid<D>::Data {
  // TODO(reader): the grid geometry, the per-block table and the kept values.
};

template <int D>
NarrowBandGrid<D>::NarrowBandGrid(const SdfGrid<D>& dense, double bandWidth, int blockSize) {
  // TODO(reader): check the arguments, then keep the blocks that touch the band.
  (void)dense;
  (void)bandWidth;
  (void)blockSize;
}

template <int D>
double NarrowBandGrid<D>::value(const Vec<D>& x) const {
  // TODO(reader): interpolate the clamped node values of x's cell.
  (void)x;
  return 0.0;
}

template <int D>
std::int64_t NarrowBandGrid<D>::storedNodes() const {
  return 0;  // TODO(reader)
}

template <int D>
std::size_t NarrowBandGrid<D>::memoryBytes() const {
  return 0;  // TODO(reader)
}

template class NarrowBandGrid<2>;
template class NarrowBandGrid<3>;

}  // namespace stackbook::exercises
