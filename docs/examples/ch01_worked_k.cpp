// Prints the worked example of chapter 1 as Markdown: a box touched at a corner, its K.
#include <iomanip>
#include <iostream>

#include "stackbook/impulse/collision_matrix.hpp"

int main() {
  using namespace stackbook;
  RigidBody<3> box = makeDynamicBody<3>(2.0, Vec3(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0));
  const Mat3 K = collisionMatrix<3>(box, Vec3(0.5, -0.5, 0.5));
  std::cout << std::setprecision(6) << "K =\n" << K << "\n";
}
