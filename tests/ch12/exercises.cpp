// Chapter 12 exercises: suite ch12_exercises, skipped by default. The exercises preset builds
// them into build/exercises/tests/ch12/test_ch12_exercises. It registers one CTest entry per
// exercise, ex12.1 to ex12.2, with the labels exercise and ch12. Run all of them, or one, with
//   ctest --preset exercises -L ch12
//   ctest --preset exercises -R ex12.1
// An entry runs its tests once its stub has no "// TODO(reader)" comment left. The binary
// runs them at any time:
//   build/exercises/tests/ch12/test_ch12_exercises --no-skip -ts=ch12_exercises -tc="Exercise 12.1*"
// They fail until you solve the exercise (the stub returns a neutral value).
// The main build runs them against the reference solutions: ctest --preset solutions -L ch12
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "ch09/stack_scenes.hpp"
#include "stackbook/exercises/ex12_1_lever_shares.hpp"
#include "stackbook/exercises/ex12_2_critical_offset.hpp"
#include "stackbook/stacking/load_carrying.hpp"

using namespace stackbook;

TEST_SUITE(STACKBOOK_CHAPTER "_exercises" * doctest::skip()) {

TEST_CASE("Exercise 12.1: the lever rule puts the load's centre where it is") {
  // Entries at -1 and 1, centre 0.5: moments about the centre balance for shares 1/4 and 3/4.
  const std::vector<double> two = leverShares(0.5, {-1.0, 1.0});
  REQUIRE(two.size() == 2);
  CHECK(two[0] == doctest::Approx(0.25).epsilon(1e-15));
  CHECK(two[1] == doctest::Approx(0.75).epsilon(1e-15));
  // Three entries: the two around the centre carry it, the far one nothing.
  const std::vector<double> three = leverShares(0.2, {-1.0, 0.0, 1.0});
  CHECK(three[0] == 0.0);
  CHECK(three[1] == doctest::Approx(0.8).epsilon(1e-15));
  CHECK(three[2] == doctest::Approx(0.2).epsilon(1e-15));
  // Outside every entry: the nearest one carries it all; one entry carries it all.
  CHECK(leverShares(2.0, {-1.0, 1.0}) == std::vector<double>{0.0, 1.0});
  CHECK(leverShares(0.3, {0.7}) == std::vector<double>{1.0});
  CHECK_THROWS_AS(leverShares(0.0, {}), std::invalid_argument);
}

TEST_CASE("Exercise 12.2: a leaning tower of n boxes carries its loads up to the offset 1 / n") {
  CHECK(criticalOffset(2) == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(criticalOffset(10) == doctest::Approx(0.1).epsilon(1e-15));
  CHECK_THROWS_AS(criticalOffset(1), std::invalid_argument);
  // The chapter's test agrees on both sides: the tower of ten carries every load just below the
  // critical offset, and not just above it.
  for (const double factor : {0.95, 1.05}) {
    CAPTURE(factor);
    const World<2> world = stacks::boxStack<2>(10, Material{0.0, 0.5, 0.0}, factor * criticalOffset(10));
    ContactGraphSettings g;
    const ContactGraph graph = worldContactGraph<2>(world, g);
    const LoadCarrying<2> c = loadCarrying<2>(world, graph, topologicalLevels(graph), g.dt, g.rotation, g.narrow, 0.0);
    CHECK((c.uncarried == 0) == (factor < 1.0));
  }
}

}  // TEST_SUITE
