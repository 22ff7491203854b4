#pragma once
/// \file
/// \brief The peers of `stackbook sweep` (chapter 11): Box2D and Bullet run on the sweep's
/// scene (a scene file of boxes) with their own knobs and measured by the same error
/// definitions as stackbook's runs (measureSweepTrajectory()).

#include <string>

#include "stackbook/peers/box_scenes.hpp"
#include "stackbook/scene/scene.hpp"

namespace peers {

/// Registers every peer this program was built with (registerSweepPeer()); the others'
/// rows are skipped with one note (sweepNotes()).
void registerSweepPeers();

/// The box scene of a loaded scene file: every body a box (its size, pose, velocities and
/// mass), gravity as a vector, one friction and restitution for every contact. Throws
/// SceneError naming `file` and the body when a body is not a box or materials differ.
BoxScene boxSceneOf(const stackbook::Scene& scene, const std::string& file);

}  // namespace peers
