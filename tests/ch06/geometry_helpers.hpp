#pragma once
// Small helpers shared by chapter 6's tests.
#include <string>

#include "stackbook/math/types.hpp"

namespace stackbook::testing {

/// True if `part` occurs in `text` (error messages name what they reject).
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// A point given by its distance from the axis (first coordinate) and its height along
/// the axis (last coordinate): (r, 0, z) in 3D, (r, z) in 2D.
template <int D>
Vec<D> at(double r, double z) {
  Vec<D> p = Vec<D>::Zero();
  p[0] = r;
  p[D - 1] = z;
  return p;
}

}  // namespace stackbook::testing
