#pragma once
// Private to the scene loader (chapter 10): building a body's shape from its "shape"
// object. See scene.hpp and docs/scene_format.md.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "stackbook/scene/scene_reader.hpp"

namespace stackbook::scene_detail {

/// A built shape with its mass properties per unit density in its body frame (centre of
/// mass at the origin, principal axes on the coordinate axes), and where that body frame
/// sits in the frame the scene places ("frame": identity for the symmetric analytic
/// shapes; the centre of mass and principal axes for meshes).
template <int D>
struct BuiltShape {
  std::shared_ptr<const Shape<D>> shape;
  SurfaceMesh<D> mesh;     ///< drawing and samples, body frame
  double measure = 0.0;    ///< area (2D) or volume (3D)
  AngVec<D> unitMoments;   ///< principal moments of inertia at density 1
  Pose<D> frame;
  /// One line per repair of a mesh loaded with "meshMode": "repair" (mesh_repair.hpp).
  std::vector<std::string> repairs;
  /// One line per defect left after repair, with what is approximate because of it.
  std::vector<std::string> approximations;
};

/// Builds the shape of `spec` (at pointer `ptr`); `baseDir` resolves mesh files.
template <int D>
BuiltShape<D> buildShape(const Reader& r, const json& spec, const std::string& ptr,
                         const std::filesystem::path& baseDir);

extern template BuiltShape<2> buildShape<2>(const Reader&, const json&, const std::string&,
                                            const std::filesystem::path&);
extern template BuiltShape<3> buildShape<3>(const Reader&, const json&, const std::string&,
                                            const std::filesystem::path&);

}  // namespace stackbook::scene_detail
