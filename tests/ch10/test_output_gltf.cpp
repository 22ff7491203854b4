// Chapter 10: the animated .glb reads back with tinygltf, with the structure the writer
// documents, and its animation replays the recorded poses at the key times.
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "output_fixtures.hpp"
#include "stackbook/output/animated_gltf.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

tinygltf::Model readGlb(const std::string& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromFile(&model, &err, &warn, path);
  INFO("tinygltf: " << err << warn);
  REQUIRE(ok);
  CHECK(err.empty());
  CHECK(warn.empty());
  return model;
}

/// The floats behind an accessor, packed (count * components).
std::vector<float> floats(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors.at(static_cast<std::size_t>(index));
  REQUIRE(accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
  const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  const auto& data = model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : sizeof(float) * std::size_t(components);
  const std::size_t start = view.byteOffset + accessor.byteOffset;
  REQUIRE(start + stride * (accessor.count - 1) + sizeof(float) * std::size_t(components) <= data.size());
  std::vector<float> out(accessor.count * std::size_t(components));
  for (std::size_t k = 0; k < accessor.count; ++k) {
    std::memcpy(&out[k * std::size_t(components)], data.data() + start + k * stride,
                sizeof(float) * std::size_t(components));
  }
  return out;
}

struct Written {
  Recording<3> recording;
  tinygltf::Model model;
};

Written writeFalling(const GlbOptions& options = {}) {
  Written w{fallingRecording3D(fewFalls(), 46, 30.0), {}};
  const auto path = scratchFolder("glb") / "falling.glb";
  writeAnimatedGlb(w.recording, path.string(), options);
  w.model = readGlb(path.string());
  return w;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE("The GLB reads back with one node per body and identical meshes shared") {
  const Written w = writeFalling();
  const tinygltf::Model& m = w.model;
  CHECK(m.asset.version == "2.0");
  // Bodies: ground, box, ball, box, ball; plus the root node.
  REQUIRE(m.nodes.size() == w.recording.bodyCount() + 1);
  REQUIRE(m.scenes.size() == 1);
  REQUIRE(m.scenes[0].nodes.size() == 1);
  const tinygltf::Node& root = m.nodes.at(std::size_t(m.scenes[0].nodes[0]));
  CHECK(root.children.size() == w.recording.bodyCount());
  // Three distinct (surface, colour) pairs and three colours; boxes 1 and 3 share a mesh.
  CHECK(m.meshes.size() == 3);
  CHECK(m.materials.size() == 3);
  CHECK(m.nodes[1].mesh == m.nodes[3].mesh);
  CHECK(m.nodes[2].mesh == m.nodes[4].mesh);
  CHECK(m.nodes[0].mesh != m.nodes[1].mesh);
  for (std::size_t i = 0; i < w.recording.bodyCount(); ++i) CHECK(m.nodes[i].name == w.recording.visuals()[i].name);
  // Accessors: POSITION and NORMAL per surface, one shared time input, two outputs per moving body.
  CHECK(m.accessors.size() == 3 * 2 + 1 + 4 * 2);
}

TEST_CASE("The GLB's flat-shaded vertices have the mesh's counts and bounds") {
  const Written w = writeFalling();
  for (std::size_t i : {std::size_t(0), std::size_t(1), std::size_t(2)}) {
    CAPTURE(i);
    const TriangleMesh& mesh = w.recording.visuals()[i].mesh;
    const tinygltf::Primitive& primitive = w.model.meshes.at(std::size_t(w.model.nodes[i].mesh)).primitives.at(0);
    CHECK(primitive.mode == TINYGLTF_MODE_TRIANGLES);
    const tinygltf::Accessor& position = w.model.accessors.at(std::size_t(primitive.attributes.at("POSITION")));
    CHECK(position.count == 3 * mesh.faces.size());
    const Aabb<3> bounds = mesh.bounds();
    REQUIRE(position.minValues.size() == 3);
    REQUIRE(position.maxValues.size() == 3);
    for (int d = 0; d < 3; ++d) {
      CHECK(position.minValues[std::size_t(d)] == double(float(bounds.lower[d])));
      CHECK(position.maxValues[std::size_t(d)] == double(float(bounds.upper[d])));
    }
    // Each flat normal is the unit outward normal of its triangle.
    const auto p = floats(w.model, primitive.attributes.at("POSITION"));
    const auto n = floats(w.model, primitive.attributes.at("NORMAL"));
    for (std::size_t t = 0; t < mesh.faces.size(); ++t) {
      const Vec3 a(p[9 * t], p[9 * t + 1], p[9 * t + 2]), b(p[9 * t + 3], p[9 * t + 4], p[9 * t + 5]),
          c(p[9 * t + 6], p[9 * t + 7], p[9 * t + 8]);
      const Vec3 expected = (b - a).cross(c - a).normalized();
      for (int k = 0; k < 3; ++k) {
        const Vec3 normal(n[9 * t + 3 * std::size_t(k)], n[9 * t + 3 * std::size_t(k) + 1], n[9 * t + 3 * std::size_t(k) + 2]);
        CHECK((normal - expected).norm() < 1e-5);
      }
    }
  }
}

TEST_CASE("The GLB animation has two LINEAR channels per moving body and none for the ground") {
  const Written w = writeFalling();
  REQUIRE(w.model.animations.size() == 1);
  const tinygltf::Animation& animation = w.model.animations[0];
  std::multiset<int> targets;
  std::set<std::string> paths;
  for (const auto& channel : animation.channels) {
    targets.insert(channel.target_node);
    paths.insert(channel.target_path);
    CHECK(animation.samplers.at(std::size_t(channel.sampler)).interpolation == "LINEAR");
  }
  CHECK(targets.count(0) == 0);
  for (int i = 1; i <= 4; ++i) CHECK(targets.count(i) == 2);
  CHECK(paths == std::set<std::string>{"rotation", "translation"});
}

TEST_CASE("The GLB sampler times are the recorded times") {
  const Written w = writeFalling();
  const tinygltf::Animation& animation = w.model.animations.at(0);
  for (const auto& sampler : animation.samplers) {
    const auto times = floats(w.model, sampler.input);
    REQUIRE(times.size() == w.recording.frameCount());
    for (std::size_t f = 0; f < times.size(); ++f) CHECK(times[f] == float(w.recording.times()[f]));
    const tinygltf::Accessor& input = w.model.accessors.at(std::size_t(sampler.input));
    CHECK(input.minValues.at(0) == double(float(w.recording.times().front())));
    CHECK(input.maxValues.at(0) == double(float(w.recording.times().back())));
  }
}

TEST_CASE("The GLB animation replays the recorded poses at the key times") {
  const Written w = writeFalling();
  const tinygltf::Animation& animation = w.model.animations.at(0);
  const auto& poses = w.recording.poses();
  for (const auto& channel : animation.channels) {
    CAPTURE(channel.target_node);
    CAPTURE(channel.target_path);
    const std::size_t i = std::size_t(channel.target_node);
    const auto values = floats(w.model, animation.samplers.at(std::size_t(channel.sampler)).output);
    if (channel.target_path == "translation") {
      REQUIRE(values.size() == 3 * poses.size());
      for (std::size_t f = 0; f < poses.size(); ++f) {
        for (int d = 0; d < 3; ++d) CHECK(std::abs(values[3 * f + std::size_t(d)] - poses[f][i].position[d]) <= 1e-6);
      }
    } else {
      REQUIRE(values.size() == 4 * poses.size());
      for (std::size_t f = 0; f < poses.size(); ++f) {
        const Eigen::Quaterniond& q = poses[f][i].orientation;
        const Eigen::Vector4d stored(values[4 * f], values[4 * f + 1], values[4 * f + 2], values[4 * f + 3]);
        // The same rotation: q or -q, component by component (x y z w order).
        const double error = std::min((stored - q.coeffs()).cwiseAbs().maxCoeff(), (stored + q.coeffs()).cwiseAbs().maxCoeff());
        CHECK(error <= 1e-6);
        if (f > 0) {  // consecutive keys on the same hemisphere: slerp takes the short arc
          const Eigen::Vector4d before(values[4 * f - 4], values[4 * f - 3], values[4 * f - 2], values[4 * f - 1]);
          CHECK(stored.dot(before) >= 0.0);
        }
      }
    }
  }
}

TEST_CASE("The GLB root node turns the chosen up direction onto glTF's y axis") {
  GlbOptions options;
  options.up = Vec3(0.0, 0.0, 1.0);
  const Written w = writeFalling(options);
  const tinygltf::Node& root = w.model.nodes.at(std::size_t(w.model.scenes.at(0).nodes.at(0)));
  REQUIRE(root.rotation.size() == 4);
  const Eigen::Quaterniond q(root.rotation[3], root.rotation[0], root.rotation[1], root.rotation[2]);
  CHECK((q * Vec3::UnitZ() - Vec3::UnitY()).norm() < 1e-12);
}

TEST_CASE("A repeated time in the recording keeps only the later frame in the GLB") {
  // glTF needs strictly increasing key times; two frames at t = 0.1 become one key,
  // holding the later pose (the state at the end of that instant).
  Recording<3> recording({{"cube", boxMesh(Vec3(1.0, 1.0, 1.0)), false, {0.2, 0.4, 0.8}}});
  for (const auto& [t, y] : {std::pair{0.0, 3.0}, std::pair{0.1, 2.0}, std::pair{0.1, 1.5}, std::pair{0.2, 1.0}}) {
    Pose<3> pose;
    pose.position = Vec3(0.0, y, 0.0);
    recording.recordPoses(t, {pose});
  }
  const auto path = scratchFolder("glbtimes") / "cube.glb";
  writeAnimatedGlb(recording, path.string());
  const tinygltf::Model model = readGlb(path.string());
  REQUIRE(model.animations.size() == 1);
  const auto& animation = model.animations[0];
  REQUIRE(animation.channels.size() == 2);
  const auto& sampler = animation.samplers.at(std::size_t(animation.channels[0].sampler));
  CHECK(floats(model, sampler.input) == std::vector<float>{0.0f, 0.1f, 0.2f});
  const auto translation = floats(model, sampler.output);
  REQUIRE(translation.size() == 9);
  CHECK(translation[4] == 1.5f);
}

TEST_CASE("Writing the GLB into a missing folder fails with the path in the message") {
  const std::string path = (scratchFolder("glbbad") / "no such folder" / "a.glb").string();
  const Recording<3> recording = fallingRecording3D(fewFalls(), 2, 30.0);
  CHECK_THROWS_WITH_AS(writeAnimatedGlb(recording, path), doctest::Contains(("cannot write '" + path + "'").c_str()),
                       std::runtime_error);
}

}  // TEST_SUITE
