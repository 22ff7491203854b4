// Exercise 5.3 (stub): a solid of revolution as a closed mesh.
// Implement: revolveProfile. Delete every TODO(reader) comment once your code is in: while one
// is left, the exercise counts as not solved and its tests do not run.
// The reference solution is chapters/solutions/ex05_3_solid_of_revolution.cpp.
#include "stackbook/exercises/ex05_3_solid_of_revolution.hpp"

namespace stackbook::exercises {

TriangleMesh revolveProfile([[maybe_unused]] const std::vector<Vec2>& profile,
                            [[maybe_unused]] int segments) {
  // TODO(reader): sweep the profile around the z axis; orient each quad so that
  // (b - a) x (c - a) points out of the solid (torusMesh shows one way).
  return TriangleMesh{};  // an empty mesh
}

}  // namespace stackbook::exercises
