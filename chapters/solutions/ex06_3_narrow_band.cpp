// Exercise 6.3, reference solution: blocks of B^D nodes; a table with one entry per block
// holds either the offset of the block's values or its sign.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "stackbook/exercises/ex06_3_narrow_band.hpp"

namespace stackbook::exercises {

template <int D>
struct NarrowBandGrid<D>::Data {
  Vec<D> origin;
  double h = 1.0;
  double width = 0.0;
  int block = 8;
  std::array<int, D> nodes{};   // node counts per axis
  std::array<int, D> blocks{};  // block counts per axis
  Aabb<D> box;
  // Per block: >= 0 the offset of its B^D values in `values`; -1 all outside; -2 all inside.
  std::vector<std::int64_t> table;
  std::vector<double> values;

  std::int64_t blockIndex(const std::array<int, D>& node) const {
    std::int64_t index = 0;
    for (int k = D - 1; k >= 0; --k) index = index * blocks[k] + node[k] / block;
    return index;
  }
  std::int64_t offsetInBlock(const std::array<int, D>& node) const {
    std::int64_t index = 0;
    for (int k = D - 1; k >= 0; --k) index = index * block + node[k] % block;
    return index;
  }
  // The clamped value at a node.
  double node(const std::array<int, D>& i) const {
    const std::int64_t entry = table[blockIndex(i)];
    if (entry == -1) return width;
    if (entry == -2) return -width;
    return values[entry + offsetInBlock(i)];
  }
  double interpolate(const Vec<D>& x) const {
    std::array<int, D> cell;
    Vec<D> t;
    for (int k = 0; k < D; ++k) {
      const double s = (x[k] - origin[k]) / h;
      cell[k] = std::clamp(static_cast<int>(std::floor(s)), 0, nodes[k] - 2);
      t[k] = std::clamp(s - cell[k], 0.0, 1.0);
    }
    double phi = 0.0;
    for (unsigned mask = 0; mask < (1u << D); ++mask) {
      std::array<int, D> corner = cell;
      double w = 1.0;
      for (int k = 0; k < D; ++k) {
        const bool upper = (mask >> k) & 1u;
        corner[k] += upper ? 1 : 0;
        w *= upper ? t[k] : 1.0 - t[k];
      }
      phi += w * node(corner);
    }
    return phi;
  }
};

template <int D>
NarrowBandGrid<D>::NarrowBandGrid(const SdfGrid<D>& dense, double bandWidth, int blockSize) {
  const double h = dense.cellSize();
  if (!(bandWidth >= std::sqrt(double(D)) * h)) {
    throw std::invalid_argument("NarrowBandGrid: bandWidth must be at least sqrt(D) h = " +
                                std::to_string(std::sqrt(double(D)) * h));
  }
  if (blockSize < 2) throw std::invalid_argument("NarrowBandGrid: blockSize must be at least 2");
  auto data = std::make_shared<Data>();
  data->origin = dense.box().lower;
  data->h = h;
  data->width = bandWidth;
  data->block = blockSize;
  data->nodes = dense.nodeCounts();
  data->box = dense.box();
  std::int64_t blockCount = 1, perBlock = 1;
  for (int k = 0; k < D; ++k) {
    data->blocks[k] = (data->nodes[k] + blockSize - 1) / blockSize;
    blockCount *= data->blocks[k];
    perBlock *= blockSize;
  }
  // First pass: which blocks touch the band, and the sign of the others.
  std::vector<char> keep(blockCount, 0), negative(blockCount, 0);
  std::int64_t total = dense.nodeCount();
  for (std::int64_t i = 0; i < total; ++i) {
    std::array<int, D> node;
    std::int64_t rest = i;
    for (int k = 0; k < D; ++k) {
      node[k] = static_cast<int>(rest % data->nodes[k]);
      rest /= data->nodes[k];
    }
    const double phi = dense.values()[i];
    const std::int64_t b = data->blockIndex(node);
    if (std::abs(phi) <= bandWidth) keep[b] = 1;
    if (phi < 0.0) negative[b] = 1;
  }
  data->table.assign(blockCount, -1);
  std::int64_t used = 0;
  for (std::int64_t b = 0; b < blockCount; ++b) {
    if (keep[b]) {
      data->table[b] = used;
      used += perBlock;
    } else if (negative[b]) {
      data->table[b] = -2;
    }
  }
  // Second pass: the clamped values of the kept blocks.
  data->values.assign(used, 0.0);
  for (std::int64_t i = 0; i < total; ++i) {
    std::array<int, D> node;
    std::int64_t rest = i;
    for (int k = 0; k < D; ++k) {
      node[k] = static_cast<int>(rest % data->nodes[k]);
      rest /= data->nodes[k];
    }
    const std::int64_t entry = data->table[data->blockIndex(node)];
    if (entry >= 0) {
      data->values[entry + data->offsetInBlock(node)] =
          std::clamp(dense.values()[i], -bandWidth, bandWidth);
    }
  }
  data_ = std::move(data);
}

template <int D>
double NarrowBandGrid<D>::value(const Vec<D>& x) const {
  if (data_->box.contains(x)) return data_->interpolate(x);
  const Vec<D> p = x.cwiseMax(data_->box.lower).cwiseMin(data_->box.upper);
  return data_->interpolate(p) + (x - p).norm();  // Eq. (6.14)
}

template <int D>
std::int64_t NarrowBandGrid<D>::storedNodes() const {
  return static_cast<std::int64_t>(data_->values.size());
}

template <int D>
std::size_t NarrowBandGrid<D>::memoryBytes() const {
  return data_->values.size() * sizeof(double) + data_->table.size() * sizeof(std::int64_t);
}

template class NarrowBandGrid<2>;
template class NarrowBandGrid<3>;

}  // namespace stackbook::exercises
