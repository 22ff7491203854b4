#pragma once
/// \file
/// \brief Mass, centre of mass and inertia tensor of a closed boundary mesh of uniform
/// density, by the divergence theorem: signed simplices (tetrahedra in 3D, triangles in 2D)
/// between an apex and each face (\ref ch05, Eqs. (5.17)-(5.22)); principal moments and
/// axes; and the move of a mesh into its body frame.
///
/// In 3D the measure is a volume and the density a mass per volume; in 2D the measure is an
/// area, the density a mass per area, and the inertia the single polar moment about the
/// axis normal to the plane.

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "stackbook/body/rigid_body.hpp"
#include "stackbook/geometry/surface_mesh.hpp"
#include "stackbook/math/pose.hpp"

namespace stackbook {

// [mass_properties_struct]
/// Mass properties of a uniform solid, in the frame of the mesh it was computed from.
template <int D>
struct MassProperties {
  double measure = 0.0;                  ///< volume (3D) or area (2D)
  double mass = 0.0;                     ///< density x measure
  Vec<D> centerOfMass = Vec<D>::Zero();  ///< c, mesh frame
  AngMat<D> inertia = AngMat<D>::Zero(); ///< inertia tensor about c, mesh-frame axes
};
// [mass_properties_struct]

/// Knobs of computeMassProperties and moveToPrincipalFrame (\ref ch05).
struct MassPropertySettings {
  /// Check that the mesh is closed and consistently oriented (every directed edge has
  /// exactly one opposite): a hole or a flipped face is reported by name rather than
  /// silently giving a wrong volume.
  bool requireClosed = true;
  /// Put the apex of the signed simplices at the centre of the mesh's bounding box instead
  /// of the origin. Far from the origin the simplices are long and thin and the shift to
  /// the centre of mass cancels digits (chapter 5, Pitfalls, measures how many).
  bool apexAtBoundsCenter = true;
  /// A measure below flatnessTolerance x (bounding-box diagonal)^D counts as zero (a flat
  /// mesh, or one whose faces cancel).
  double flatnessTolerance = 1e-12;
  /// Principal moments closer than this fraction of the trace are treated as equal; the
  /// axes inside such a cluster are then chosen closest to the mesh's own axes.
  double equalMomentTolerance = 1e-9;
};

namespace detail {

template <int D>
void requireValidMesh(const char* context, const SurfaceMesh<D>& mesh,
                      const MassPropertySettings& settings) {
  const auto fail = [context](const std::string& what) {
    throw std::invalid_argument(std::string(context) + ": " + what);
  };
  if (mesh.faces.empty()) fail("the mesh has no faces");
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      std::ostringstream msg;
      msg << "vertex " << v << " is not finite (" << mesh.vertices[v].transpose() << ")";
      fail(msg.str());
    }
  }
  std::vector<std::pair<int, int>> edges;  // directed boundary edges (a, b) of every face
  edges.reserve(mesh.faces.size() * static_cast<std::size_t>(D == 3 ? 3 : 1));
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int k = 0; k < D; ++k) {
      const int i = mesh.faces[f][static_cast<std::size_t>(k)];
      if (i < 0 || i >= n) {
        std::ostringstream msg;
        msg << "face " << f << " refers to vertex " << i << ", but there are " << n
            << " vertices";
        fail(msg.str());
      }
    }
    if constexpr (D == 3) {
      for (std::size_t k = 0; k < 3; ++k) {
        edges.emplace_back(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]);
      }
    } else {
      edges.emplace_back(mesh.faces[f][0], mesh.faces[f][1]);
    }
  }
  if (!settings.requireClosed) return;
  std::sort(edges.begin(), edges.end());
  if constexpr (D == 3) {
    // Closed and consistently oriented: each directed edge (a, b) occurs once and so does
    // its reverse (b, a), which the neighbouring face traverses the other way.
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges[e];
      if (e + 1 < edges.size() && edges[e + 1] == edges[e]) {
        std::ostringstream msg;
        msg << "edge (" << a << ", " << b << ") is traversed twice in the same direction: "
            << "neighbouring faces are oriented inconsistently, or the mesh is non-manifold";
        fail(msg.str());
      }
      if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) {
        std::ostringstream msg;
        msg << "edge (" << a << ", " << b << ") has no opposite edge (" << b << ", " << a
            << "): the mesh is open (it has a hole or a dangling face)";
        fail(msg.str());
      }
    }
  } else {
    // Closed boundary: every vertex ends as many segments as it starts.
    std::vector<int> balance(static_cast<std::size_t>(n), 0);
    for (const auto& [a, b] : edges) {
      ++balance[static_cast<std::size_t>(a)];
      --balance[static_cast<std::size_t>(b)];
    }
    for (std::size_t v = 0; v < balance.size(); ++v) {
      if (balance[v] != 0) {
        std::ostringstream msg;
        msg << "vertex " << v << " starts " << (balance[v] > 0 ? "more" : "fewer")
            << " segments than it ends: the polygon is open or inconsistently oriented";
        fail(msg.str());
      }
    }
  }
}

}  // namespace detail

// [compute_mass_properties]
/// Mass properties of the solid bounded by a closed, outward-oriented mesh of uniform
/// density (\ref ch05). Each face and the apex span a signed simplex; summing the simplices'
/// volume, first moment and second moment gives those of the solid (Eqs. (5.17)-(5.21)).
/// Throws std::invalid_argument when the density is not finite and positive, the mesh is
/// empty, open, inconsistently oriented or has a non-finite vertex, or its volume is not
/// positive (an inside-out mesh).
template <int D>
MassProperties<D> computeMassProperties(const SurfaceMesh<D>& mesh, double density = 1.0,
                                        const MassPropertySettings& settings = {}) {
  const char* context = "computeMassProperties";
  if (!std::isfinite(density) || !(density > 0.0)) {
    std::ostringstream msg;
    msg << context << ": density must be finite and positive, got " << density;
    throw std::invalid_argument(msg.str());
  }
  detail::requireValidMesh<D>(context, mesh, settings);
  const Aabb<D> box = mesh.bounds();
  const Vec<D> apex = settings.apexAtBoundsCenter ? box.center() : Vec<D>::Zero();

  // Sums over the signed simplices, relative to the apex, for unit density.
  double measure = 0.0;               // integral of 1
  Vec<D> first = Vec<D>::Zero();      // integral of x
  Mat<D> second = Mat<D>::Zero();     // integral of x x^T
  for (const std::array<int, D>& face : mesh.faces) {
    const Vec<D> a = mesh.vertices[static_cast<std::size_t>(face[0])] - apex;
    const Vec<D> b = mesh.vertices[static_cast<std::size_t>(face[1])] - apex;
    if constexpr (D == 3) {
      const Vec3 c = mesh.vertices[static_cast<std::size_t>(face[2])] - apex;
      const double v = a.dot(b.cross(c)) / 6.0;  // Eq. (5.17)
      const Vec3 s = a + b + c;
      measure += v;
      first += (v / 4.0) * s;  // Eq. (5.18)
      second += (v / 20.0) *
                (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
      // Eq. (5.19)
    } else {
      const double area = 0.5 * (a.x() * b.y() - a.y() * b.x());  // Eq. (5.21)
      const Vec2 s = a + b;
      measure += area;
      first += (area / 3.0) * s;  // Eq. (5.21)
      second += (area / 12.0) * (a * a.transpose() + b * b.transpose() + s * s.transpose());
      // Eq. (5.21)
    }
  }
  const double scale = std::pow(box.extent().norm(), D);
  if (!(measure > settings.flatnessTolerance * scale)) {
    std::ostringstream msg;
    msg << context << ": the enclosed " << (D == 3 ? "volume" : "area") << " is " << measure
        << ", not positive: the mesh is inside-out (faces oriented inward"
        << (D == 3 ? "" : ", a clockwise polygon") << "), flat, or open";
    throw std::invalid_argument(msg.str());
  }
  const Vec<D> centroid = first / measure;  // relative to the apex
  // Parallel-axis shift of the second moment to the centroid, Eq. (5.20).
  const Mat<D> secondAtCentroid = second - measure * centroid * centroid.transpose();

  MassProperties<D> result;
  result.measure = measure;
  result.mass = density * measure;
  result.centerOfMass = apex + centroid;
  if constexpr (D == 3) {
    result.inertia = density * (secondAtCentroid.trace() * Mat3::Identity() - secondAtCentroid);
    result.inertia = 0.5 * (result.inertia + result.inertia.transpose()).eval();
  } else {
    result.inertia(0, 0) = density * secondAtCentroid.trace();  // polar moment, Eq. (5.21)
  }
  if (!std::isfinite(result.mass) || !result.centerOfMass.allFinite() ||
      !result.inertia.allFinite()) {
    throw std::invalid_argument(std::string(context) +
                                ": the mass properties overflowed (coordinates or density too "
                                "large for double precision)");
  }
  return result;
}
// [compute_mass_properties]

// [principal_frame]
/// Principal moments and axes of an inertia tensor (\ref ch05, Eq. (5.22)).
template <int D>
struct PrincipalAxes {
  AngVec<D> moments = AngVec<D>::Zero();              ///< principal moments, body axis order
  Orientation<D> rotation = identityOrientation<D>(); ///< body axes in the input frame
};

/// Diagonalise the inertia tensor of `properties`: I = R diag(moments) R^T, with R a proper
/// rotation whose columns (the principal axes) are chosen as close as possible to the input
/// frame's axes, so an axis-aligned box keeps its axes and a slightly rotated one is
/// rotated back. Equal moments (within settings.equalMomentTolerance of the trace) leave the
/// axes in their plane free; they are then the input axes projected into that plane.
/// In 2D the inertia is the single polar moment and the rotation the identity.
/// Throws std::invalid_argument if the mass or the tensor is not finite, the tensor is not
/// symmetric, or the moments are not positive or violate the triangle inequality.
template <int D>
PrincipalAxes<D> principalAxes(const MassProperties<D>& properties,
                               const MassPropertySettings& settings = {}) {
  const char* context = "principalAxes";
  const AngMat<D>& I = properties.inertia;
  if (!I.allFinite()) {
    throw std::invalid_argument(std::string(context) + ": the inertia tensor is not finite");
  }
  PrincipalAxes<D> axes;
  if constexpr (D == 2) {
    // The plane has one rotation axis and a 1 x 1 inertia: nothing to diagonalise.
    axes.moments = I.diagonal();
  } else {
    const double trace = I.trace();
    if (!((I - I.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * std::abs(trace))) {
      throw std::invalid_argument(std::string(context) + ": the inertia tensor is not symmetric");
    }
    const Eigen::SelfAdjointEigenSolver<Mat3> solver(I);
    if (solver.info() != Eigen::Success) {
      throw std::invalid_argument(std::string(context) + ": the eigensolver failed");
    }
    const Vec3 lambda = solver.eigenvalues();  // ascending
    Mat3 Q = solver.eigenvectors();
    const double tol = settings.equalMomentTolerance * std::abs(trace);
    const bool lowPair = lambda[1] - lambda[0] <= tol;
    const bool highPair = lambda[2] - lambda[1] <= tol;
    if (lowPair && highPair) {
      Q.setIdentity();  // isotropic: every axis is principal, keep the input axes
    } else if (lowPair || highPair) {
      // One distinct axis u; the other two span its orthogonal plane. Take the input axes
      // least aligned with u and project them into that plane.
      const int distinct = lowPair ? 2 : 0;
      const Vec3 u = Q.col(distinct);
      Eigen::Index k0 = 0;
      u.cwiseAbs().maxCoeff(&k0);  // the input axis that u replaces
      const Vec3 e1 = Mat3::Identity().col((k0 + 1) % 3);
      const Vec3 v1 = (e1 - e1.dot(u) * u).normalized();
      const Vec3 v2 = u.cross(v1);
      Q.col(0) = u;
      Q.col(1) = v1;
      Q.col(2) = v2;
    }
    // Assign eigenvector columns to input axes: the permutation with the largest total
    // alignment |Q(axis, column)|, ties broken by the fixed enumeration order.
    static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int best = 0;
    double bestScore = -1.0;
    for (int p = 0; p < 6; ++p) {
      double score = 0.0;
      for (int c = 0; c < 3; ++c) score += std::abs(Q(perms[p][c], c));
      if (score > bestScore + 1e-12) {
        bestScore = score;
        best = p;
      }
    }
    Mat3 R;
    for (int c = 0; c < 3; ++c) {
      const int axis = perms[best][c];
      R.col(axis) = Q(axis, c) < 0.0 ? Vec3(-Q.col(c)) : Vec3(Q.col(c));
    }
    if (R.determinant() < 0.0) {
      // A reflection: flip the axis that is least aligned with its input axis.
      Eigen::Index worst = 0;
      R.diagonal().cwiseAbs().minCoeff(&worst);
      R.col(worst) = -R.col(worst);
    }
    axes.rotation = Eigen::Quaterniond(R).normalized();
    const Mat3 Rn = axes.rotation.toRotationMatrix();
    axes.moments = (Rn.transpose() * I * Rn).diagonal();  // Eq. (5.22)
  }
  validateMassProperties<D>(context, properties.mass, axes.moments);
  return axes;
}
// [principal_frame]

// [move_to_principal_frame]
/// What moveToPrincipalFrame did and found.
template <int D>
struct BodyFrame {
  double mass = 0.0;                           ///< m
  AngVec<D> principalMoments = AngVec<D>::Zero(); ///< I_body, for makeDynamicBody
  /// The body frame in the mesh's original coordinates: its origin is the centre of mass
  /// and its axes the principal axes, so an original point is frame.toWorld(body point).
  Pose<D> frame;
};

/// Move a closed mesh into its body frame (\ref ch05): translate the centre of mass to the
/// origin and rotate the principal axes onto the coordinate axes, p <- R^T (p - c).
/// Returns the mass, the principal moments and the frame used. Throws like
/// computeMassProperties and principalAxes.
template <int D>
BodyFrame<D> moveToPrincipalFrame(SurfaceMesh<D>& mesh, double density = 1.0,
                                  const MassPropertySettings& settings = {}) {
  const MassProperties<D> properties = computeMassProperties<D>(mesh, density, settings);
  const PrincipalAxes<D> axes = principalAxes<D>(properties, settings);
  BodyFrame<D> result;
  result.mass = properties.mass;
  result.principalMoments = axes.moments;
  result.frame = Pose<D>{properties.centerOfMass, axes.rotation};
  for (Vec<D>& p : mesh.vertices) p = result.frame.toBody(p);
  return result;
}

/// A dynamic body made from a mesh (\ref ch05): the mesh is moved into its body frame
/// (moveToPrincipalFrame) and the body is placed so that the mesh sits where `placement`
/// puts the original mesh: body pose = placement composed with the body frame.
template <int D>
RigidBody<D> makeBodyFromMesh(SurfaceMesh<D>& mesh, double density = 1.0,
                              const Pose<D>& placement = Pose<D>{},
                              const MassPropertySettings& settings = {}) {
  const BodyFrame<D> frame = moveToPrincipalFrame<D>(mesh, density, settings);
  RigidBody<D> body = makeDynamicBody<D>(frame.mass, frame.principalMoments);
  body.position = placement.toWorld(frame.frame.position);
  if constexpr (D == 2) {
    body.orientation = Eigen::Rotation2Dd(placement.orientation.angle() +
                                          frame.frame.orientation.angle());
  } else {
    body.orientation = (placement.orientation * frame.frame.orientation).normalized();
  }
  return body;
}
// [move_to_principal_frame]

}  // namespace stackbook
