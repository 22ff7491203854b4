#pragma once
/// \file
/// \brief Axis-aligned bounding boxes in D dimensions.

#include <limits>

#include "stackbook/math/types.hpp"

namespace stackbook {

template <int D>
struct Aabb {
  Vec<D> lower = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> upper = Vec<D>::Constant(-std::numeric_limits<double>::infinity());

  bool isEmpty() const { return (lower.array() > upper.array()).any(); }
  void extend(const Vec<D>& p) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  void extend(const Aabb& other) {
    lower = lower.cwiseMin(other.lower);
    upper = upper.cwiseMax(other.upper);
  }
  Aabb inflated(double margin) const {
    return Aabb{Vec<D>(lower.array() - margin), Vec<D>(upper.array() + margin)};
  }
  bool contains(const Vec<D>& p) const {
    return (p.array() >= lower.array()).all() && (p.array() <= upper.array()).all();
  }
  bool overlaps(const Aabb& other) const {
    return (lower.array() <= other.upper.array()).all() &&
           (other.lower.array() <= upper.array()).all();
  }
  Vec<D> extent() const { return upper - lower; }
  Vec<D> center() const { return 0.5 * (lower + upper); }
};

}  // namespace stackbook
