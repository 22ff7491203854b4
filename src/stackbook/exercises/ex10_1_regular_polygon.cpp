// Exercise 10.1 (your answer goes here): see ex10_1_regular_polygon.hpp and chapter 10.
// Implement: regularPolygonShape. Delete every TODO(reader) comment once your code is in: while
// one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex10_1_regular_polygon.hpp"

namespace stackbook {

PolygonShapeBuild regularPolygonShape(const nlohmann::json& spec) {
  // TODO(reader): check the fields, build the counterclockwise corner loop, a GridShape<2>
  // over it, and the area and polar moment (sum over the n triangles centre-corner-corner).
  (void)spec;
  return {};
}

}  // namespace stackbook
