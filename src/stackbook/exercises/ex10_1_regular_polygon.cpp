// Exercise 10.1 (your answer goes here): see ex10_1_regular_polygon.hpp and chapter 10.
#include "stackbook/exercises/ex10_1_regular_polygon.hpp"

namespace stackbook {

PolygonShapeBuild regularPolygonShape(const nlohmann::json& spec) {
  // TODO(reader): check the fields, build the counterclockwise corner loop, a GridShape<2>
  // over it, and the area and polar moment (sum over the n triangles centre-corner-corner).
  (void)spec;
  return {};
}

}  // namespace stackbook
