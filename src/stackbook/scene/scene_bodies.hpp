#pragma once
// Private to the scene loader (chapter 10): building the bodies of a scene from its
// "bodies" array, and the start-overlap check. See scene.hpp and docs/scene_format.md.
#include <filesystem>
#include <map>
#include <string>

#include "stackbook/scene/scene_reader.hpp"

namespace stackbook::scene_detail {

/// The bodies of `doc` in dimension D, with gravity `gravity`; unless `allowOverlap`,
/// bodies that start inside each other are rejected.
template <int D>
SceneBodies<D> buildBodies(const Reader& r, const json& doc, const std::map<std::string, Material>& materials,
                           const std::filesystem::path& baseDir, const Vec<D>& gravity, bool allowOverlap);

extern template SceneBodies<2> buildBodies<2>(const Reader&, const json&, const std::map<std::string, Material>&,
                                              const std::filesystem::path&, const Vec<2>&, bool);
extern template SceneBodies<3> buildBodies<3>(const Reader&, const json&, const std::map<std::string, Material>&,
                                              const std::filesystem::path&, const Vec<3>&, bool);

}  // namespace stackbook::scene_detail
