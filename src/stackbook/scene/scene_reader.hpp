#pragma once
// Private to the scene loader (chapter 10): the typed reader every part of the loader
// uses, so that each failure is a SceneError naming the file and the JSON pointer, and
// the readers of the scene's settings objects. See scene.hpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stackbook/scene/scene.hpp"

namespace stackbook::scene_detail {

using nlohmann::json;

/// `key` as one RFC 6901 reference token ("~" -> "~0", "/" -> "~1").
std::string escapePointerToken(const std::string& key);

/// A short account of a JSON value for "got ..." in messages.
std::string describeValue(const json& v);

/// `x` with ten significant digits, for messages.
std::string formatNumber(double x);

/// Reads the parts of one scene file; every failure is a SceneError with this file's name.
class Reader {
 public:
  explicit Reader(std::string file, const SceneLimits& limits = {}) : file_(std::move(file)), limits_(limits) {}
  const SceneLimits& limits() const { return limits_; }

  [[noreturn]] void fail(const std::string& pointer, const std::string& reason,
                         std::vector<std::string> details = {}) const {
    throw SceneError(file_, pointer, reason, std::move(details));
  }
  const std::string& file() const { return file_; }

  /// `v` must be an object whose keys are all in `allowed`.
  void requireObject(const json& v, const std::string& ptr, const std::vector<std::string>& allowed,
                     const std::string& what) const {
    if (!v.is_object()) fail(ptr, "expected " + what + " (a JSON object), got " + describeValue(v));
    for (const auto& item : v.items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      std::string reason = "unknown field \"" + printable(item.key()) + "\" in " + what;
      const std::string hint = closestName(item.key(), allowed);
      if (!hint.empty()) {
        reason += "; did you mean \"" + hint + "\"?";
      } else {
        reason += "; allowed:";
        for (std::size_t k = 0; k < allowed.size(); ++k) reason += (k ? ", " : " ") + allowed[k];
      }
      fail(ptr + "/" + escapePointerToken(item.key()), reason);
    }
  }

  double number(const json& v, const std::string& ptr) const {
    if (!v.is_number()) fail(ptr, "expected a number, got " + describeValue(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(ptr, "must be a finite number");
    if (!(std::abs(x) <= limits_.numberMagnitude)) {
      fail(ptr, "must be at most " + formatNumber(limits_.numberMagnitude) + " in magnitude (a limit of the scene format), got " +
                    formatNumber(x));
    }
    return x;
  }
  double positive(const json& v, const std::string& ptr) const {
    const double x = number(v, ptr);
    if (!(x > 0.0)) fail(ptr, "must be > 0, got " + formatNumber(x));
    if (x < limits_.smallestPositive) {
      fail(ptr, "must be at least " + formatNumber(limits_.smallestPositive) + " (a limit of the scene format), got " +
                    formatNumber(x));
    }
    return x;
  }
  double nonNegative(const json& v, const std::string& ptr) const {
    const double x = number(v, ptr);
    if (!(x >= 0.0)) fail(ptr, "must be >= 0, got " + formatNumber(x));
    return x;
  }
  double inRange(const json& v, const std::string& ptr, double lo, double hi) const {
    const double x = number(v, ptr);
    if (!(x >= lo && x <= hi)) {
      fail(ptr, "must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], got " +
                    formatNumber(x));
    }
    return x;
  }
  int integer(const json& v, const std::string& ptr, int least, int most = 1'000'000'000) const {
    if (!v.is_number_integer()) fail(ptr, "expected an integer, got " + describeValue(v));
    // An unsigned value beyond the signed range is larger than any limit (not negative).
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(most)) {
      fail(ptr, "must be an integer in [" + std::to_string(least) + ", " + std::to_string(most) + "], got " +
                    std::to_string(v.get<std::uint64_t>()));
    }
    const auto x = v.get<std::int64_t>();
    if (x < least || x > most) {
      fail(ptr, "must be an integer in [" + std::to_string(least) + ", " + std::to_string(most) +
                    "], got " + std::to_string(x));
    }
    return static_cast<int>(x);
  }
  bool boolean(const json& v, const std::string& ptr) const {
    if (!v.is_boolean()) fail(ptr, "expected true or false, got " + describeValue(v));
    return v.get<bool>();
  }
  std::string string(const json& v, const std::string& ptr) const {
    if (!v.is_string()) fail(ptr, "expected a string, got " + describeValue(v));
    return v.get<std::string>();
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vector(const json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != static_cast<std::size_t>(N)) {
      fail(ptr, "expected an array of " + std::to_string(N) + " numbers, got " + describeValue(v));
    }
    Eigen::Matrix<double, N, 1> out;
    for (int k = 0; k < N; ++k) {
      out[k] = number(v[static_cast<std::size_t>(k)], ptr + "/" + std::to_string(k));
    }
    return out;
  }
  template <int N>
  Eigen::Matrix<double, N, 1> positiveVector(const json& v, const std::string& ptr) const {
    const Eigen::Matrix<double, N, 1> out = vector<N>(v, ptr);
    for (int k = 0; k < N; ++k) {
      const std::string at = ptr + "/" + std::to_string(k);
      if (!(out[k] > 0.0)) fail(at, "must be > 0, got " + formatNumber(out[k]));
      if (out[k] < limits_.smallestPositive) {
        fail(at, "must be at least " + formatNumber(limits_.smallestPositive) + " (a limit of the scene format), got " +
                     formatNumber(out[k]));
      }
    }
    return out;
  }

 private:
  std::string file_;
  SceneLimits limits_;
};

/// The member `key` of object `obj`, or nullptr.
inline const json* member(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

/// The "solver" object into `s`.
void readSolver(const Reader& r, const json& solver, StepSettings& s);

/// The "effects" object into `e`.
void readEffects(const Reader& r, const json& effects, EffectOverrides& e);

/// The "materials" object: each named material.
std::map<std::string, Material> readMaterials(const Reader& r, const json& materials);

}  // namespace stackbook::scene_detail
