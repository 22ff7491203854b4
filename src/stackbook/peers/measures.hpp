#pragma once
// What peers_bench measures after a run, the same way for every engine: drift, sag, speed,
// penetration (from the boxes' geometry, by the separating-axis test) and energy.
#include <vector>

#include <Eigen/Core>

#include "stackbook/peers/box_scenes.hpp"

namespace peers {

/// A body's state as an engine reports it, in 3D (2D: the x-y plane, z = 0, rotation about z).
struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< centre of mass
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();
};

/// The accuracy columns of the table. Negative values mean "not measured".
struct Accuracy {
  double drift = -1.0;        ///< largest horizontal distance of a body's centre from its start (m)
  double sag = -1.0;          ///< how far the top box sank (m; > 0 is down)
  double maxSpeed = -1.0;     ///< largest |v| + |omega| * half-diagonal (m/s)
  double penetration = -1.0;  ///< deepest overlap of two bodies (m)
  double energyChange = 0.0;  ///< E_end - E_start (J), kinetic + potential
  /// Incline scenes: how far the block slid along x, over the closed form, minus 1 (and the
  /// closed form itself); not measured elsewhere.
  double inclineError = -2.0;
  double inclineDistance = -1.0;
  bool finite = true;
};

/// Kinetic + potential energy of the dynamic boxes (uniform boxes: I = m (a^2 + b^2) / 12).
double boxEnergy(const BoxScene& scene, const std::vector<BodyState>& states);

/// The deepest overlap between any two boxes (the ground included) at the given states: for
/// each pair, the smallest overlap of their projections over the separating axes (2 face
/// normals each in 2D; 3 each and 9 edge crossings in 3D), 0 when an axis separates them.
double boxPenetration(const BoxScene& scene, const std::vector<BodyState>& states);

/// Drift, sag, speed, penetration and energy change of a box scene between two states
/// `seconds` apart (every body, the ground first, in the scene's order).
Accuracy boxAccuracy(const BoxScene& scene, const std::vector<BodyState>& start,
                     const std::vector<BodyState>& end, double seconds);

}  // namespace peers
