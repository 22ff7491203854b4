#pragma once
/// \file
/// \brief Where one impulse of a pair acts (\ref ch08, "Where the impulse acts",
/// Eqs. (8.10)-(8.12)): GBF's deepest approaching sample, or the depth-weighted centre of
/// the approaching samples that share its normal.

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "stackbook/collision/narrow_phase.hpp"

namespace stackbook {

// [impulse_point_settings]
/// The rule that picks the point an impulse of a pair acts at.
enum class ImpulsePointRule {
  /// GBF: the deepest approaching sample (Eq. (7.6)). Two samples of equal depth (a box
  /// flat on a face) are split by round-off and taken one after the other.
  Deepest,
  /// The depth-weighted centre of the approaching samples whose normal is within
  /// `normalCosine` of the deepest one's (Eq. (8.10)): one sample gives GBF's point, a
  /// flat face gives its middle, a tilting face leans to its deep side continuously.
  DepthWeightedCentre,
  /// The sticking patch (chapter 8, "A whole patch at once", Eq. (8.16)): when the pair
  /// touches along a patch of samples that share the deepest one's normal, one impulse and
  /// one angular impulse stop the pair's whole relative motion, if friction and the patch
  /// can carry them (Eqs. (8.18), (8.19)); otherwise GBF's deepest sample, as Deepest.
  StickingPatch,
};

struct ImpulsePointSettings {
  ImpulsePointRule rule = ImpulsePointRule::Deepest;
  /// A sample joins the centre when its normal n_i (turned to the deepest sample's
  /// owner) has n_i . n >= normalCosine (in (0, 1]; 0.99 is 8.1 degrees). Faces of a
  /// nonconvex body that meet at a sharper angle get their own impulses.
  double normalCosine = 0.99;
  /// Where the approach test and the impulse measure lever arms and the normal (chapter 8,
  /// "A rocking block", Eq. (8.22)): at the tested pose where the sample was found (Eq. (8.3),
  /// the default), or at the pose the step started from (PhysBAM's; the default step's).
  LeverArms arms = LeverArms::AtTestedPose;
  /// Held samples (chapter 12, "Landing on a support", Eq. (12.6)): the collision stage passes
  /// over an approaching sample that interferes only because of the step's loads while a sample
  /// of the pair at least as deep rests, and leaves it to the contact stage. false (the
  /// default): every approaching sample can collide (the rule of Eq. (7.6) alone).
  bool heldSamples = false;
  /// Tied landing (chapter 12, "Landing on a support", Eq. (12.7)): the approaching samples
  /// whose depth is within tieTolerance |phi| of the chosen one's, with its normal, share one
  /// impulse at their centre. false (the default): ties are taken one after the other, in the
  /// order round-off gives them (GBF's rule alone).
  bool tiedLanding = false;
  /// The relative depth within which samples tie (>= 0; 1e-6: equal but for round-off).
  double tieTolerance = 1e-6;
};
// [impulse_point_settings]

/// Throws std::invalid_argument unless normalCosine is in (0, 1] and tieTolerance is finite and >= 0.
inline void validateImpulsePointSettings(const ImpulsePointSettings& s, const char* caller) {
  std::ostringstream msg;
  if (!(s.normalCosine > 0.0 && s.normalCosine <= 1.0)) {
    msg << caller << ": settings.impulsePoint.normalCosine must be in (0, 1], got " << s.normalCosine;
  } else if (!(std::isfinite(s.tieTolerance) && s.tieTolerance >= 0.0)) {
    msg << caller << ": settings.impulsePoint.tieTolerance must be finite and >= 0, got " << s.tieTolerance;
  } else {
    return;
  }
  throw std::invalid_argument(msg.str());
}

// [landing_rules]
/// The landing rules on (chapter 8, "A rocking block"; chapter 12, "Landing on a support"):
/// lever arms at the start pose (Eq. (8.22)), held samples (Eq. (12.6)) and tied landing
/// (Eq. (12.7)). The default step (the preset "carryingPass") turns them on; StepSettings{}
/// keeps the paper's pair rule.
inline ImpulsePointSettings withLandingRules(ImpulsePointSettings s) {
  s.arms = LeverArms::AtStartPose;
  s.heldSamples = true;
  s.tiedLanding = true;
  return s;
}
// [landing_rules]

// [tied_landing_point]
/// The tied landing of Eq. (12.7) over a list of samples: the centre of the approaching
/// samples of `samples` whose depth is within ties.depthTolerance |phi| of `chosen`'s and
/// whose normal, turned to its owner, lies within ties.normalCosine of its normal (chosen
/// among them). `chosen` itself when it is alone.
template <int D>
InterferenceSample<D> tiedLandingPoint(const InterferenceSample<D>& chosen, const std::vector<InterferenceSample<D>>& samples,
                                       const std::vector<CollisionBody<D>>& bodies, const TiedLanding& ties) {
  const double reach = ties.depthTolerance * std::abs(chosen.depth);
  Vec<D> sum = Vec<D>::Zero();
  int members = 0;
  for (const InterferenceSample<D>& s : samples) {
    if (!(s.depth - chosen.depth <= reach)) continue;
    const double sign = s.owner == chosen.owner ? 1.0 : -1.0;  // turned to the chosen sample's owner
    if (!(sign * s.normal.dot(chosen.normal) >= ties.normalCosine)) continue;
    if (!(normalRelativeVelocity<D>(s, bodies) < 0.0)) continue;  // Eq. (7.5)
    sum += s.point;
    ++members;
  }
  if (members < 2) return chosen;
  InterferenceSample<D> centre = chosen;
  centre.point = sum / static_cast<double>(members);  // Eq. (12.7)
  centre.sampleIndex = -1;
  return centre;
}
// [tied_landing_point]

// [impulse_point]
/// The sample one impulse of the pair acts at, or empty when no sample approaches.
/// Deepest (and StickingPatch, whose single point is GBF's): deepestApproachingSample().
/// DepthWeightedCentre: with n the deepest
/// approaching sample's normal, the centre p = sum w_i p_i / sum w_i over the approaching
/// samples i whose normal, turned to the deepest sample's owner, lies within
/// normalCosine of n, with weights w_i = -phi_i, the depth (Eq. (8.10)). The result keeps
/// the deepest sample's owner, normal and depth; its sampleIndex is -1 when it is a
/// centre of several. The relative velocity is affine in the point, so the centre of
/// approaching samples approaches along n unless their normals differ (Eq. (8.11)); if it
/// does not, the deepest sample is returned.
template <int D>
std::optional<InterferenceSample<D>> impulsePoint(const std::vector<InterferenceSample<D>>& samples,
                                                  const std::vector<CollisionBody<D>>& bodies,
                                                  const ImpulsePointSettings& settings,
                                                  DetectionCounters* counters = nullptr) {
  const std::optional<InterferenceSample<D>> deepest = deepestApproachingSample<D>(samples, bodies, counters);
  if (!deepest || settings.rule != ImpulsePointRule::DepthWeightedCentre) return deepest;
  Vec<D> weighted = Vec<D>::Zero();
  double total = 0.0;
  int members = 0;
  for (const InterferenceSample<D>& s : samples) {
    const double sign = s.owner == deepest->owner ? 1.0 : -1.0;  // turn to the deepest's owner
    if (sign * s.normal.dot(deepest->normal) < settings.normalCosine) continue;
    if (!(normalRelativeVelocity<D>(s, bodies) < 0.0)) continue;  // Eq. (7.5)
    const double w = -s.depth;
    weighted += w * s.point;
    total += w;
    ++members;
  }
  if (members < 2 || !(total > 0.0)) return deepest;
  InterferenceSample<D> centre = *deepest;
  centre.point = weighted / total;  // Eq. (8.10)
  centre.sampleIndex = -1;
  if (!(normalRelativeVelocity<D>(centre, bodies) < 0.0)) return deepest;  // Eq. (8.11)
  return centre;
}
// [impulse_point]

}  // namespace stackbook
