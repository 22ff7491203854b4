#include "stackbook/output/animated_gltf.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "stackbook/output/output_files.hpp"

namespace stackbook {

namespace {

/// Append floats to the buffer and make a buffer view over them; returns its index.
int addFloatView(tinygltf::Model& model, const std::vector<float>& values, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  const std::size_t offset = data.size();  // always a multiple of 4: only floats go in
  data.resize(offset + values.size() * sizeof(float));
  std::memcpy(data.data() + offset, values.data(), values.size() * sizeof(float));
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = values.size() * sizeof(float);
  if (target != 0) view.target = target;
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

/// A float accessor of `components` per element over new data; min/max when asked.
int addFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int type, int components,
                     int target, bool withBounds) {
  tinygltf::Accessor accessor;
  accessor.bufferView = addFloatView(model, values, target);
  accessor.byteOffset = 0;
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = type;
  accessor.count = values.size() / static_cast<std::size_t>(components);
  if (withBounds) {
    accessor.minValues.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::infinity());
    accessor.maxValues.assign(static_cast<std::size_t>(components), -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < values.size(); ++k) {
      const std::size_t c = k % static_cast<std::size_t>(components);
      accessor.minValues[c] = std::min(accessor.minValues[c], static_cast<double>(values[k]));
      accessor.maxValues[c] = std::max(accessor.maxValues[c], static_cast<double>(values[k]));
    }
  }
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

double srgbToLinear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

bool sameMesh(const TriangleMesh& a, const TriangleMesh& b) {
  return a.faces == b.faces && a.vertices.size() == b.vertices.size() &&
         std::equal(a.vertices.begin(), a.vertices.end(), b.vertices.begin(),
                    [](const Vec3& p, const Vec3& q) { return p == q; });
}

/// Flat-shaded POSITION and NORMAL accessors of a mesh; returns {position, normal}.
std::pair<int, int> addGeometry(tinygltf::Model& model, const TriangleMesh& mesh, const std::string& name) {
  std::vector<float> positions, normals;
  positions.reserve(mesh.faces.size() * 9);
  normals.reserve(mesh.faces.size() * 9);
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    for (int k : face) {
      if (k < 0 || k >= n) {
        throw std::invalid_argument("writeAnimatedGlb: body '" + name + "': triangle " + std::to_string(f) +
                                    " refers to a missing vertex");
      }
    }
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(face[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(face[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(face[2])];
    Vec3 normal = (b - a).cross(c - a);
    normal = normal.norm() > 0.0 ? Vec3(normal.normalized()) : Vec3::UnitY();
    for (const Vec3* v : {&a, &b, &c}) {
      for (int d = 0; d < 3; ++d) {
        positions.push_back(static_cast<float>((*v)[d]));
        normals.push_back(static_cast<float>(normal[d]));
      }
    }
  }
  const int position = addFloatAccessor(model, positions, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  const int normal = addFloatAccessor(model, normals, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  return {position, normal};
}

}  // namespace

void writeAnimatedGlb(const Recording<3>& recording, const std::string& path, const GlbOptions& options) {
  if (recording.frameCount() == 0) {
    throw std::invalid_argument("writeAnimatedGlb: the recording has no frame (writing '" + path + "')");
  }
  if (recording.times().front() < 0.0) {
    throw std::invalid_argument("writeAnimatedGlb: glTF animation times must be >= 0, the recording starts at " +
                                output_detail::exactDecimal(recording.times().front()));
  }
  if (!options.up.allFinite() || !(options.up.norm() > 0.0)) {
    throw std::invalid_argument("writeAnimatedGlb: GlbOptions::up must be a finite nonzero vector");
  }
  const auto& visuals = recording.visuals();
  const auto& poses = recording.poses();
  const auto& times = recording.times();

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "stackbook";
  model.buffers.emplace_back();

  // Materials: one per distinct colour.
  std::vector<std::array<double, 3>> colors;
  std::vector<int> materialOf(visuals.size());
  for (std::size_t i = 0; i < visuals.size(); ++i) {
    const auto it = std::find(colors.begin(), colors.end(), visuals[i].color);
    materialOf[i] = static_cast<int>(it - colors.begin());
    if (it != colors.end()) continue;
    colors.push_back(visuals[i].color);
    tinygltf::Material material;
    material.name = "colour " + std::to_string(colors.size() - 1);
    material.pbrMetallicRoughness.baseColorFactor = {srgbToLinear(visuals[i].color[0]),
                                                     srgbToLinear(visuals[i].color[1]),
                                                     srgbToLinear(visuals[i].color[2]), 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    model.materials.push_back(material);
  }

  // Geometry: one accessor pair per distinct surface; meshes: one per (surface, colour).
  std::vector<std::size_t> geometryOwner;  // body whose mesh defines geometry g
  std::vector<std::pair<int, int>> geometryAccessors;
  std::vector<std::pair<int, int>> meshKeys;  // (geometry, material) of mesh m
  std::vector<int> meshOf(visuals.size());
  for (std::size_t i = 0; i < visuals.size(); ++i) {
    std::size_t g = 0;
    while (g < geometryOwner.size() && !sameMesh(visuals[geometryOwner[g]].mesh, visuals[i].mesh)) ++g;
    if (g == geometryOwner.size()) {
      geometryOwner.push_back(i);
      geometryAccessors.push_back(addGeometry(model, visuals[i].mesh, visuals[i].name));
    }
    const std::pair<int, int> key(static_cast<int>(g), materialOf[i]);
    const auto it = std::find(meshKeys.begin(), meshKeys.end(), key);
    meshOf[i] = static_cast<int>(it - meshKeys.begin());
    if (it != meshKeys.end()) continue;
    meshKeys.push_back(key);
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = geometryAccessors[g].first;
    primitive.attributes["NORMAL"] = geometryAccessors[g].second;
    primitive.material = key.second;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "mesh " + std::to_string(meshKeys.size() - 1);
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
  }

  // Keyframes: strictly increasing times (the later of equal times wins).
  std::vector<std::size_t> keys;
  for (std::size_t f = 0; f < times.size(); ++f) {
    if (!keys.empty() && times[f] == times[keys.back()]) keys.back() = f;
    else keys.push_back(f);
  }

  // Nodes: a root that turns `up` onto +y, and one child per body at the first pose.
  tinygltf::Node root;
  root.name = "stackbook";
  const Eigen::Quaterniond toYUp = Eigen::Quaterniond::FromTwoVectors(options.up.normalized(), Vec3::UnitY());
  if (!toYUp.isApprox(Eigen::Quaterniond::Identity())) root.rotation = {toYUp.x(), toYUp.y(), toYUp.z(), toYUp.w()};
  for (std::size_t i = 0; i < visuals.size(); ++i) {
    tinygltf::Node node;
    node.name = visuals[i].name.empty() ? "body " + std::to_string(i) : visuals[i].name;
    node.mesh = meshOf[i];
    const Pose<3>& pose = poses.front()[i];
    node.translation = {pose.position.x(), pose.position.y(), pose.position.z()};
    const Eigen::Quaterniond& q = pose.orientation;
    node.rotation = {q.x(), q.y(), q.z(), q.w()};
    model.nodes.push_back(node);
    root.children.push_back(static_cast<int>(i));
  }
  // Contacts: one node per keyframe whose step applied impulses (drawn in world frame).
  std::vector<std::pair<std::size_t, int>> contactNodes;  // (key index, node)
  if (options.drawContacts && !recording.contacts().empty()) {
    Aabb<3> box;
    for (std::size_t i = 0; i < visuals.size(); ++i) {
      for (const Vec3& v : visuals[i].mesh.vertices) box.extend(poses.front()[i].toWorld(v));
    }
    const double extent = box.isEmpty() ? 1.0 : std::max(box.extent().maxCoeff(), 1e-300);
    const double length = options.contactNormalFraction * extent;
    tinygltf::Material material;
    material.name = "contacts";
    material.pbrMetallicRoughness.baseColorFactor = {srgbToLinear(options.contactColor[0]),
                                                     srgbToLinear(options.contactColor[1]),
                                                     srgbToLinear(options.contactColor[2]), 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.emissiveFactor = material.pbrMetallicRoughness.baseColorFactor;
    material.emissiveFactor.resize(3);
    model.materials.push_back(material);
    const int contactMaterial = static_cast<int>(model.materials.size()) - 1;
    const auto& contacts = recording.contacts();
    std::size_t next = 0;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      std::vector<float> points, lines;
      for (; next < contacts.size() && contacts[next].frame <= keys[k]; ++next) {
        const RecordedContact& c = contacts[next];
        if (c.frame != keys[k] || c.time != times[keys[k]]) continue;
        for (int d = 0; d < 3; ++d) points.push_back(static_cast<float>(c.contact.point[static_cast<std::size_t>(d)]));
        for (int d = 0; d < 3; ++d) lines.push_back(static_cast<float>(c.contact.point[static_cast<std::size_t>(d)]));
        for (int d = 0; d < 3; ++d) {
          const auto u = static_cast<std::size_t>(d);
          lines.push_back(static_cast<float>(c.contact.point[u] + length * c.contact.normal[u]));
        }
      }
      if (points.empty()) continue;
      tinygltf::Mesh mesh;
      mesh.name = "contacts at " + output_detail::exactDecimal(times[keys[k]]) + " s";
      for (const auto& [values, mode] : {std::pair{&points, TINYGLTF_MODE_POINTS}, std::pair{&lines, TINYGLTF_MODE_LINE}}) {
        tinygltf::Primitive primitive;
        primitive.attributes["POSITION"] =
            addFloatAccessor(model, *values, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
        primitive.material = contactMaterial;
        primitive.mode = mode;
        mesh.primitives.push_back(primitive);
      }
      model.meshes.push_back(mesh);
      tinygltf::Node node;
      node.name = mesh.name;
      node.mesh = static_cast<int>(model.meshes.size()) - 1;
      if (keys.size() >= 2) node.scale = {0.0, 0.0, 0.0};  // hidden but at its own keyframe
      model.nodes.push_back(node);
      const int index = static_cast<int>(model.nodes.size()) - 1;
      root.children.push_back(index);
      contactNodes.emplace_back(k, index);
    }
  }
  model.nodes.push_back(root);
  tinygltf::Scene scene;
  scene.name = "stackbook";
  scene.nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  tinygltf::Animation animation;
  animation.name = "stackbook run";
  int input = -1;
  for (std::size_t i = 0; i < visuals.size() && keys.size() >= 2; ++i) {
    bool moving = false;
    for (std::size_t f : keys) {
      moving = moving || poses[f][i].position != poses.front()[i].position ||
               !(poses[f][i].orientation.coeffs() == poses.front()[i].orientation.coeffs());
    }
    if (!moving) continue;
    if (input < 0) {
      std::vector<float> t;
      for (std::size_t f : keys) t.push_back(static_cast<float>(times[f]));
      input = addFloatAccessor(model, t, TINYGLTF_TYPE_SCALAR, 1, 0, true);
    }
    std::vector<float> translation, rotation;
    Eigen::Vector4d previous = poses[keys.front()][i].orientation.coeffs();  // x y z w
    for (std::size_t f : keys) {
      const Pose<3>& pose = poses[f][i];
      for (int d = 0; d < 3; ++d) translation.push_back(static_cast<float>(pose.position[d]));
      Eigen::Vector4d q = pose.orientation.normalized().coeffs();
      if (q.dot(previous) < 0.0) q = -q;  // q and -q are the same rotation: keep the short arc
      previous = q;
      for (int d = 0; d < 4; ++d) rotation.push_back(static_cast<float>(q[d]));
    }
    const int node = static_cast<int>(i);
    const std::pair<const char*, int> channels[] = {
        {"translation", addFloatAccessor(model, translation, TINYGLTF_TYPE_VEC3, 3, 0, false)},
        {"rotation", addFloatAccessor(model, rotation, TINYGLTF_TYPE_VEC4, 4, 0, false)}};
    for (const auto& [target, output] : channels) {
      tinygltf::AnimationSampler sampler;
      sampler.input = input;
      sampler.output = output;
      sampler.interpolation = "LINEAR";
      animation.samplers.push_back(sampler);
      tinygltf::AnimationChannel channel;
      channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
      channel.target_node = node;
      channel.target_path = target;
      animation.channels.push_back(channel);
    }
  }
  for (const auto& [k, node] : contactNodes) {
    if (keys.size() < 2) break;
    if (input < 0) {
      std::vector<float> t;
      for (std::size_t f : keys) t.push_back(static_cast<float>(times[f]));
      input = addFloatAccessor(model, t, TINYGLTF_TYPE_SCALAR, 1, 0, true);
    }
    std::vector<float> scale;
    for (std::size_t j = 0; j < keys.size(); ++j) {
      for (int d = 0; d < 3; ++d) scale.push_back(j == k ? 1.0f : 0.0f);
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = addFloatAccessor(model, scale, TINYGLTF_TYPE_VEC3, 3, 0, false);
    sampler.interpolation = "STEP";  // visible from its keyframe to the next
    animation.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = "scale";
    animation.channels.push_back(channel);
  }
  if (!animation.channels.empty()) model.animations.push_back(animation);
  model.buffers[0].name = "stackbook data";

  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, false, true)) {
    throw std::runtime_error("writeAnimatedGlb: tinygltf could not serialise the model for '" + path + "'");
  }
  output_detail::writeFileOrThrow("writeAnimatedGlb", path, bytes.str());
}

}  // namespace stackbook
