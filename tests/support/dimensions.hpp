#pragma once
// Run one test in 2D and in 3D:
//   TEST_CASE_TEMPLATE("claim", Dim, In2D, In3D) { constexpr int D = Dim::value; ... }
// CTest then lists "chNN/claim<2D>" and "chNN/claim<3D>".
// Test names must not contain commas: doctest's --test-case filter splits on them,
// and CTest discovery would lose the chapter label.
#include <type_traits>

#include <doctest/doctest.h>

namespace stackbook::testing {
using In2D = std::integral_constant<int, 2>;
using In3D = std::integral_constant<int, 3>;
}  // namespace stackbook::testing

TYPE_TO_STRING_AS("2D", stackbook::testing::In2D);
TYPE_TO_STRING_AS("3D", stackbook::testing::In3D);
