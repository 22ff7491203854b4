#pragma once
// Chapter 8's test scenes (scene_builders.hpp) and the one doctest helper the tests add.
#include <doctest/doctest.h>

#include "scene_builders.hpp"

namespace stackbook::testing {

/// doctest's Approx with a purely relative tolerance. Approx(x).epsilon(r) alone accepts
/// r (1 + max(|a|, |b|)), which for values below 1 is an absolute tolerance r.
inline doctest::Approx within(double expected, double relative) {
  return doctest::Approx(expected).epsilon(relative).scale(0.0);
}

}  // namespace stackbook::testing
