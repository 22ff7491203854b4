#pragma once
// Recordings for the output writers' tests (chapter 10), built from closed-form motion,
// no simulator: boxes that fall freely from rest (y = y0 - g t^2 / 2) while spinning at a
// constant rate, and stop (and stop spinning) on the ground at y = rest. The poses at
// every frame are known exactly, so a writer's output can be checked against them.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "stackbook/geometry/mesh_primitives.hpp"
#include "stackbook/output/recording.hpp"

namespace stackbook::testing {

inline constexpr double kFixtureGravity = 9.81;

/// One falling body: start height, resting height, spin rate (rad/s) and, in 3D, axis.
struct Fall {
  double x = 0.0, z = 0.0, y0 = 1.0, rest = 0.5, spin = 0.0;
  Vec3 axis = Vec3::UnitZ();
  /// Time at which it lands: y0 - g t^2 / 2 = rest.
  double landing() const { return std::sqrt(2.0 * (y0 - rest) / kFixtureGravity); }
  double height(double t) const { return std::max(rest, y0 - 0.5 * kFixtureGravity * t * t); }
  double angle(double t) const { return spin * std::min(t, landing()); }
};

/// A 2D scene: a static ground slab (top at y = 0) and `falls` as unit-ish boxes (and,
/// when asked, an annulus as the last body: outer and inner loop).
inline Recording<2> fallingRecording2D(const std::vector<Fall>& falls, int frames, double fps,
                                       bool withAnnulus = false) {
  std::vector<BodyVisual<2>> visuals;
  visuals.push_back({"ground", rectanglePolygon(Vec2(12.0, 1.0)), true, {0.5, 0.5, 0.5}});
  for (std::size_t k = 0; k < falls.size(); ++k) {
    visuals.push_back({"box " + std::to_string(k), rectanglePolygon(Vec2(1.0, 0.8)), false,
                       {0.2 + 0.1 * double(k % 5), 0.45, 0.8 - 0.1 * double(k % 5)}});
  }
  if (withAnnulus) {
    Polygon ring = regularPolygon(0.6, 24);
    const Polygon hole = regularPolygon(0.3, 16);
    const int base = static_cast<int>(ring.vertices.size());
    // The hole runs clockwise: vertices in the same order, segments reversed.
    for (const Vec2& v : hole.vertices) ring.vertices.push_back(v);
    for (const auto& face : hole.faces) ring.faces.push_back({base + face[1], base + face[0]});
    visuals.push_back({"ring, with a hole", ring, false, {0.9, 0.6, 0.2}});
  }
  Recording<2> recording(visuals);
  for (int f = 0; f < frames; ++f) {
    const double t = f / fps;
    std::vector<Pose<2>> poses;
    Pose<2> ground;
    ground.position = Vec2(0.0, -0.5);
    poses.push_back(ground);
    for (const Fall& fall : falls) {
      Pose<2> pose;
      pose.position = Vec2(fall.x, fall.height(t));
      pose.orientation = Eigen::Rotation2Dd(fall.angle(t));
      poses.push_back(pose);
    }
    if (withAnnulus) {
      Pose<2> pose;
      pose.position = Vec2(-4.0, std::max(0.6, 4.0 - 0.5 * kFixtureGravity * t * t));
      // A fast spin, its angle wrapped into [-pi, pi] as a simulator may report it: the
      // writer must unwrap it so that the drawing does not spin back at each wrap.
      pose.orientation = Eigen::Rotation2Dd(std::remainder(10.0 * t, 2.0 * M_PI));
      poses.push_back(pose);
    }
    recording.recordPoses(t, poses);
  }
  return recording;
}

/// A 3D scene, y up: a static ground slab (top at y = 0), boxes for even k and icospheres
/// for odd k. Bodies of the same kind share one mesh and colour, as in a scene file.
inline Recording<3> fallingRecording3D(const std::vector<Fall>& falls, int frames, double fps) {
  std::vector<BodyVisual<3>> visuals;
  visuals.push_back({"ground", boxMesh(Vec3(12.0, 1.0, 12.0)), true, {0.5, 0.5, 0.5}});
  for (std::size_t k = 0; k < falls.size(); ++k) {
    if (k % 2 == 0) visuals.push_back({"box " + std::to_string(k), boxMesh(Vec3(1.0, 0.8, 0.6)), false, {0.2, 0.45, 0.8}});
    else visuals.push_back({"ball " + std::to_string(k), icosphereMesh(0.5, 1), false, {0.9, 0.5, 0.2}});
  }
  Recording<3> recording(visuals);
  for (int f = 0; f < frames; ++f) {
    const double t = f / fps;
    std::vector<Pose<3>> poses;
    Pose<3> ground;
    ground.position = Vec3(0.0, -0.5, 0.0);
    poses.push_back(ground);
    for (const Fall& fall : falls) {
      Pose<3> pose;
      pose.position = Vec3(fall.x, fall.height(t), fall.z);
      pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(fall.angle(t), fall.axis.normalized()));
      // q and -q are the same rotation; a recording may switch between them (here every
      // other frame of the last body), and the writer must not let slerp take the long arc.
      if (&fall == &falls.back() && f % 2 == 1) pose.orientation.coeffs() *= -1.0;
      poses.push_back(pose);
    }
    recording.recordPoses(t, poses);
  }
  return recording;
}

/// A few boxes dropped from different heights with different spins.
inline std::vector<Fall> fewFalls() {
  return {{-2.5, 0.0, 3.0, 0.4, 1.5, Vec3(0, 0, 1)},
          {0.0, 1.0, 5.0, 0.5, -2.0, Vec3(1, 0, 1)},
          {2.5, -1.0, 4.0, 0.4, 3.0, Vec3(1, 1, 0)},
          {1.0, 2.0, 6.5, 0.5, 0.7, Vec3(0, 1, 0)}};
}

/// `count` bodies on a grid, dropped from staggered heights (for file-size checks).
inline std::vector<Fall> manyFalls(int count) {
  std::vector<Fall> falls;
  for (int k = 0; k < count; ++k) {
    const int col = k % 10, row = k / 10;
    falls.push_back({-5.0 + 1.1 * col, -5.0 + 1.1 * row, 2.0 + 1.3 * row + 0.2 * col, 0.5,
                     0.5 + 0.1 * (k % 7), Vec3(1.0 + 0.1 * (k % 3), 1.0, 0.3 * (k % 5))});
  }
  return falls;
}

/// A fresh folder under the system temp folder for one test's files, removed when the
/// test program exits.
inline std::filesystem::path scratchFolder(const std::string& name) {
  struct Cleanup {
    std::vector<std::filesystem::path> folders;
    ~Cleanup() {
      std::error_code ignored;
      for (const auto& folder : folders) std::filesystem::remove_all(folder, ignored);
    }
  };
  static Cleanup cleanup;
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("stackbook_ch10_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  cleanup.folders.push_back(folder);
  return folder;
}

inline std::string readWhole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace stackbook::testing
