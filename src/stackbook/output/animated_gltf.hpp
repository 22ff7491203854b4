#pragma once
/// \file
/// \brief A 3D recording as an animated binary glTF 2.0 file (.glb) that opens in Blender,
/// three.js and any glTF viewer (chapter 10).

#include <string>

#include "stackbook/output/recording.hpp"

namespace stackbook {

// [glb_options]
/// How writeAnimatedGlb maps the simulation's world onto glTF's.
struct GlbOptions {
  /// The world direction that should appear as "up". glTF is y-up; a scene with gravity
  /// along -z sets (0, 0, 1), and the writer puts every body under one root node that
  /// rotates this direction onto +y. The bodies' own nodes keep world coordinates.
  Vec3 up = Vec3::UnitY();
  /// Draw, at each keyframe, the contacts of the step that reached it
  /// (Recording::contacts()): points and normal lines in one node per keyframe, shown
  /// from that keyframe to the next by a STEP scale channel (0 hides it).
  bool drawContacts = false;
  /// Length of a drawn normal as a fraction of the largest extent of the first frame.
  double contactNormalFraction = 0.03;
  /// sRGB colour of the contact points and normals.
  std::array<double, 3> contactColor{0.84, 0.15, 0.16};
};
// [glb_options]

// [write_animated_glb]
/// Write `recording` to `path` as binary glTF 2.0:
/// - one mesh per distinct (surface, colour) pair, flat-shaded (each triangle has its own
///   three vertices and its face normal), bodies with identical meshes share one;
/// - one material per distinct colour (sRGB in the BodyVisual, converted to glTF's linear
///   baseColorFactor; metallic 0, roughness 0.8);
/// - one node per body, named after it, placed at the first frame's pose, children of a
///   root node "stackbook" that rotates GlbOptions::up onto +y;
/// - one animation "stackbook run" with a LINEAR translation and a LINEAR rotation
///   channel (quaternion x y z w, signs chosen so consecutive keys have a non-negative dot
///   product) for every body that moves; all samplers share one input accessor holding
///   the recorded times (frames with a repeated time are dropped, the later one kept).
///
/// glTF stores float32, so positions and quaternions are rounded to about 7 significant
/// digits. Throws std::invalid_argument if the recording has no frame, a time is negative,
/// or a mesh refers to a missing vertex; std::runtime_error naming `path` if it cannot be
/// written.
void writeAnimatedGlb(const Recording<3>& recording, const std::string& path,
                      const GlbOptions& options = {});
// [write_animated_glb]

}  // namespace stackbook
