// Chapter 1's worked example: a unit cube resting on a static floor, touched at a bottom
// corner. Every number in the example on the chapter page comes from this program; its
// output (HTML, see ch01_html.hpp) is shown with \htmlinclude ch01_worked_k.out.
#include <iostream>
#include <string>

#include <Eigen/Eigenvalues>

#include "ch01_html.hpp"
#include "stackbook/impulse/collision_matrix.hpp"

using namespace stackbook;
using ch01_html::bmatrix;
using ch01_html::num;
using ch01_html::paragraph;
using ch01_html::tuple;

int main() {
  // A cube of side 1 and mass 2: I = m (1 + 1)/12 about each principal axis.
  const double m = 2.0;
  const double side = 1.0;
  const double I0 = m * (side * side + side * side) / 12.0;
  RigidBody<3> cube = makeDynamicBody<3>(m, Vec3(I0, I0, I0));
  cube.position = Vec3(0.0, 0.0, 0.5);  // resting on the floor z = 0
  const RigidBody<3> floor = makeStaticBody<3>();

  const Vec3 p(0.5, 0.5, 0.0);  // the bottom corner, where it touches the floor
  const Vec3 ra = p - cube.position;
  const Vec3 rb = p - floor.position;

  const Mat3 rs = crossMatrix<3>(ra);
  const Mat3 Iinv = cube.inverseInertiaWorld();
  const Mat3 K = pairCollisionMatrix<3>(cube, ra, floor, rb);
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(K);
  const Vec3 n(0.0, 0.0, 1.0);

  std::cout << paragraph(
      "A cube of side " + num(side) + " and mass \\f$m = " + num(m) +
      "\\f$ rests on a static floor, its centre at \\f$\\vb{x} = " + tuple(cube.position) +
      "\\f$. Its principal moments are \\f$m(1^2 + 1^2)/12 = " + num(I0) +
      "\\f$, so \\f$\\Iinv = " + num(1.0 / I0) +
      "\\,\\Id\\f$ in any orientation. It touches the floor at the corner \\f$\\vb{p} = " +
      tuple(p) + "\\f$, so \\f$\\rv_a = \\vb{p} - \\vb{x} = " + tuple(ra) + "\\f$ and");
  std::cout << paragraph("\\f[ \\rstar = " + bmatrix(rs) + ", \\qquad \\Iinv = " + bmatrix(Iinv) +
                         ", \\f]");
  std::cout << paragraph("\\f[ \\KT = \\Kmat_{cube} + \\Kmat_{floor} = \\frac{\\Id}{" + num(m) +
                         "} + \\rstar^T\\Iinv\\rstar + \\mathbf{0} = " + bmatrix(K) + ". \\f]");

  // The hand check with the isotropic form K = (1/m + |r|^2/I) delta - r r^T / I.
  const double diagonalPart = 1.0 / m + ra.squaredNorm() / I0;
  const double offDiagonal = ra.x() * ra.x() / I0;
  std::cout << paragraph(
      "By hand: the cube is isotropic, so \\f$\\Kmat = (1/m + \\lVert\\rv\\rVert^2/I)\\Id - "
      "\\rv\\rv^T/I\\f$, with \\f$1/m + \\lVert\\rv\\rVert^2/I = " + num(1.0 / m) + " + " +
      num(ra.squaredNorm()) + "/" + num(I0) + " = " + num(diagonalPart) +
      "\\f$ and \\f$r_i r_k/I = \\pm" + num(offDiagonal) + "\\f$: the diagonal is \\f$" +
      num(diagonalPart) + " - " + num(offDiagonal) + " = " + num(diagonalPart - offDiagonal) +
      "\\f$ and the off-diagonal entries are \\f$-r_i r_k/I = \\pm" + num(offDiagonal) + "\\f$.");

  std::cout << paragraph(
      "The eigenvalues of \\f$\\KT\\f$ are \\f$" + num(eigen.eigenvalues()[0]) + ", " +
      num(eigen.eigenvalues()[1]) + ", " + num(eigen.eigenvalues()[2]) +
      "\\f$. The smallest is \\f$1/m = " + num(1.0 / m) +
      "\\f$, along the direction \\f$\\pm" + tuple(eigen.eigenvectors().col(0)) +
      "\\f$, which is \\f$\\pm\\rv_a/\\lVert\\rv_a\\rVert\\f$: a push through the centre of mass "
      "does not turn the cube. Along the floor normal \\f$\\nv = " + tuple(n) +
      "\\f$, \\f$\\nv^T\\KT\\nv = " + num(n.dot(K * n)) +
      "\\f$: the corner responds to a vertical push like a free particle of mass "
      "\\f$1/(\\nv^T\\KT\\nv) = " + num(1.0 / n.dot(K * n)) + "\\f$, a quarter of the cube's.");

  // Apply one impulse and measure what it does.
  RigidBody<3> moving = cube;
  moving.velocity = Vec3(0.3, 0.0, -1.0);
  moving.setAngularVelocity(Vec3(0.0, 0.5, 0.0));
  RigidBody<3> ground = floor;
  const Vec3 j(0.2, 0.0, 1.0);
  const Vec3 before = relativeVelocity<3>(moving, ra, ground, rb);
  const Vec3 v0 = moving.velocity, w0 = moving.angularVelocity, L0 = moving.angularMomentum;
  applyPairImpulse<3>(moving, ra, ground, rb, j);
  const Vec3 after = relativeVelocity<3>(moving, ra, ground, rb);

  std::cout << paragraph(
      "Now let the cube arrive with \\f$\\vv = " + tuple(v0) + "\\f$ and \\f$\\wv = " +
      tuple(w0) + "\\f$, so that the corner moves at \\f$\\uv_{rel} = \\vv + \\wv\\times\\rv_a = " +
      tuple(before) + "\\f$, and apply \\f$\\jv = " + tuple(j) +
      "\\f$ at the corner (and \\f$-\\jv\\f$ to the floor):");
  std::cout << ch01_html::table(
      {"quantity", "before", "after", "change", "predicted"},
      {{"\\f$\\vv\\f$", tuple(v0), tuple(moving.velocity), tuple(moving.velocity - v0),
        "\\f$\\jv/m = " + tuple(j / m) + "\\f$ by (1.1)"},
       {"\\f$\\Lv\\f$", tuple(L0), tuple(moving.angularMomentum),
        tuple(moving.angularMomentum - L0),
        "\\f$\\rv_a\\times\\jv = " + tuple(ra.cross(j)) + "\\f$ by (1.2)"},
       {"\\f$\\wv\\f$", tuple(w0), tuple(moving.angularVelocity),
        tuple(moving.angularVelocity - w0),
        "\\f$\\Iinv\\rstar\\jv = " + tuple(Iinv * rs * j) + "\\f$ by (1.5)"},
       {"\\f$\\uv_{rel}\\f$", tuple(before), tuple(after), tuple(after - before),
        "\\f$\\KT\\jv = " + tuple(K * j) + "\\f$ by (1.10)"}});

  const double mismatch = (after - before - K * j).cwiseAbs().maxCoeff();
  std::cout << paragraph(
      "The measured change of the corner's velocity and \\f$\\KT\\jv\\f$ " +
      (mismatch == 0.0 ? std::string("agree to the last bit")
                       : "differ by at most " + num(mismatch, 2) + ", rounding") +
      ". The floor has not moved: its velocity is still " + tuple(ground.velocity) +
      " and its angular momentum " + tuple(ground.angularMomentum) + ".");
}
