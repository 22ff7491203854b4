#pragma once
/// \file
/// \brief Exercise 10.2: a new scene, generated: a row of dominoes on the ground, the first
/// one tipped over, as a scene document that loadScene's checks accept (\ref ch10).

#include <nlohmann/json.hpp>

namespace stackbook {

/// The row: `count` upright boxes `thickness` wide and `height` tall, their centres
/// `spacing` apart along +x, on a static ground.
struct DominoRow {
  int count = 5;
  double height = 1.0;     ///< m
  double thickness = 0.2;  ///< m
  double spacing = 0.55;   ///< m, centre to centre (must exceed thickness, below height)
  /// rad/s: the first domino starts turning clockwise (towards +x) at this rate about its
  /// bottom corner on the +x side, as a rigid rotation about that corner.
  double push = 2.0;
  double friction = 0.6;   ///< mu of every contact
  double dt = 0.002;       ///< s
  double duration = 2.5;   ///< s
};

/// A 2D scene document (the format of docs/scene_format.md) for `row`: "dimension" 2,
/// "dt" and "duration" from the row, one material "wood" with the row's friction and no
/// restitution, body 0 the static ground (top face at y = 0, reaching at least one height
/// beyond both ends of the row), and bodies 1..count the dominoes, standing on the ground
/// with domino k's centre at x = (k - 1) spacing. The first has angular velocity -push and
/// the velocity of a rotation about its bottom corner (thickness / 2, 0) from its bottom
/// centre: v = push (height / 2, thickness / 2).
/// Throws std::invalid_argument if count < 1 or a length is not positive and finite, or
/// spacing is not in (thickness, height).
nlohmann::json dominoRowScene(const DominoRow& row = {});

}  // namespace stackbook
