#pragma once
/// \file
/// \brief Exercise 10.3: a new output, a 3D recording as a sequence of Wavefront OBJ files
/// (one per frame), the format every modelling program imports (\ref ch10).

#include <cstddef>
#include <string>
#include <vector>

#include "stackbook/output/recording.hpp"

namespace stackbook {

/// Writes frame `frame` of `recording` to `path` as Wavefront OBJ text. For each body i in
/// order: a line `o NAME` (its BodyVisual name), then one `v x y z` line per vertex of its
/// mesh moved to the world by the body's pose at that frame (x_world = p + R x_body), then
/// one `f a b c` line per triangle with 1-based indices into the file's vertex list (so the
/// indices of body i are offset by the vertex counts of bodies 0..i-1). Coordinates are
/// written so that they read back as the same doubles (std::to_chars). Throws
/// std::out_of_range if `frame` >= recording.frameCount(), std::runtime_error naming
/// `path` if the file cannot be written.
void writeObjFrame(const Recording<3>& recording, std::size_t frame, const std::string& path);

/// Writes every frame f to `directory`/frame_NNNNN.obj (f with 5 digits, zero-padded, so
/// the names sort in time order), creating the directory if needed, and returns the paths
/// in frame order.
std::vector<std::string> writeObjSequence(const Recording<3>& recording, const std::string& directory);

}  // namespace stackbook
