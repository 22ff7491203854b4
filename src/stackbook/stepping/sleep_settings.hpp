#pragma once
/// \file
/// \brief The knobs of sleeping (chapter 8, "Sleeping"): when a body counts as at rest,
/// how long its island must rest before it sleeps, and what wakes it.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace stackbook {

// [sleep_settings]
/// When bodies fall asleep and what wakes them. Off by default: a sleeping body stops
/// creeping, so sleep changes results (a little) where bodies rest, and GBF's method does
/// not sleep; the course's measurements of the method are made awake.
struct SleepSettings {
  /// Sleep at all.
  bool enabled = false;
  /// A body is at rest while |v| < linearSpeed (m/s, >= 0) ...
  double linearSpeed = 0.05;
  /// ... and |omega| < angularSpeed (rad/s, >= 0).
  double angularSpeed = 0.05;
  /// An island falls asleep when all its bodies have been at rest this long (s, >= 0).
  double time = 0.5;
  /// A sleeping island wakes when the box of an awake dynamic body, at its predicted pose
  /// (Eq. (8.1)), comes within this distance of the box of one of its bodies (m, >= 0;
  /// the broad phase's own margin if that is larger).
  double wakeMargin = 0.01;
};
// [sleep_settings]

/// Throws std::invalid_argument naming the field unless the sleep settings are in range.
inline void validateSleepSettings(const SleepSettings& s, const char* caller) {
  std::ostringstream msg;
  const auto check = [&msg](double v, const char* name) {
    if (msg.str().empty() && !(std::isfinite(v) && v >= 0.0)) {
      msg << "sleep." << name << " must be finite and >= 0, got " << v;
    }
  };
  check(s.linearSpeed, "linearSpeed");
  check(s.angularSpeed, "angularSpeed");
  check(s.time, "time");
  check(s.wakeMargin, "wakeMargin");
  if (!msg.str().empty()) throw std::invalid_argument(std::string(caller) + ": settings." + msg.str());
}

}  // namespace stackbook
