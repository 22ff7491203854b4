#pragma once
/// \file
/// \brief Narrow phase: the surface samples of one body that lie inside another
/// (phi < 0), in both directions, and the choice of the deepest approaching one
/// (\ref ch07, Eqs. (7.1)-(7.7)).

#include <algorithm>
#include <limits>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/collision/candidate_lists.hpp"
#include "stackbook/collision/collision_body.hpp"
#include "stackbook/collision/detection_counters.hpp"
#include "stackbook/geometry/sample_chunks.hpp"

namespace stackbook {

// [interference_sample]
/// A surface sample of body `owner` found inside body `other` (\ref ch07).
/// The impulse of chapter 8 acts at `point` along `normal`: +j on the owner, -j on the
/// other body, with u_rel = u_owner - u_other (Eq. (7.4)).
template <int D>
struct InterferenceSample {
  Vec<D> point = Vec<D>::Zero();   ///< the sample's world position (owner at its tested pose)
  double depth = 0.0;              ///< phi_other at the sample: negative, -depth = distance inside
  Vec<D> normal = Vec<D>::Zero();  ///< unit outward normal of the penetrated body there, world frame
  int owner = -1;                  ///< index of the body the sample belongs to
  int other = -1;                  ///< index of the penetrated body
  int sampleIndex = -1;            ///< index in the owner's surfaceSamples(); kDeepestPointSample for an exact deepest point
  /// A point of the owner's body, carried with it (a surface sample, or a centre of samples), as
  /// opposed to an exact deepest point (chapter 11), which is where the shape's surface is deepest
  /// at the tested pose and no fixed point of the body (chapter 8, Eq. (8.22)).
  bool isBodyPoint() const;
};
/// The sampleIndex of an exact deepest point (chapter 11).
inline constexpr int kDeepestPointSample = -2;
template <int D>
bool InterferenceSample<D>::isBodyPoint() const {
  return sampleIndex != kDeepestPointSample;
}
// [interference_sample]

namespace detail {

template <int D>
void checkPose(const Pose<D>& pose, int index, const char* caller) {
  // Rotation2Dd stores an angle, Quaterniond four coefficients.
  bool finite = pose.position.allFinite();
  if constexpr (D == 2) {
    finite = finite && std::isfinite(pose.orientation.angle());
  } else {
    finite = finite && pose.orientation.coeffs().allFinite();
  }
  if (finite) return;
  std::ostringstream msg;
  msg << caller << ": body " << index << " has a non-finite pose (position "
      << pose.position.transpose() << ")";
  throw std::invalid_argument(msg.str());
}

template <int D>
[[noreturn]] void throwNanDistance(const Shape<D>& shape, const Vec<D>& x, int index) {
  std::ostringstream msg;
  msg << "appendSamplesInside: the signed distance of body " << index << " (" << shape.describe()
      << ") is NaN at body-frame point (" << x.transpose() << ")";
  throw std::domain_error(msg.str());
}

// [pose_with_matrix]
/// Pose::toWorld() and Pose::directionToWorld() with the pose's rotation matrix R already
/// at hand. In 2D Eigen's rotation of a vector is R v with R rebuilt from the angle (a sine
/// and a cosine) on every call, so R v with the R the caller holds gives the same bits at
/// no trigonometric cost. In 3D the quaternion's own formula rounds differently from R v,
/// so it is kept: the result is bit for bit what the pose computes.
template <int D>
Vec<D> poseToWorld(const Pose<D>& pose, const Mat<D>& R, const Vec<D>& p) {
  if constexpr (D == 2) {
    return pose.position + R * p;
  } else {
    (void)R;
    return pose.toWorld(p);
  }
}

template <int D>
Vec<D> poseDirectionToWorld(const Pose<D>& pose, const Mat<D>& R, const Vec<D>& d) {
  if constexpr (D == 2) {
    (void)pose;
    return R * d;
  } else {
    (void)R;
    return pose.directionToWorld(d);
  }
}
// [pose_with_matrix]

// [near_samples]
/// The runs of consecutive surface samples of `owner` that may land in `boxB` under
/// x -> M s + t (Eq. (7.2)), in ascending order: with culling on and chunks at hand, the runs
/// (SampleChunks) whose box meets boxB carried back into the owner's frame, the box of
/// M^T (boxB - t) (as Eq. (7.8) boxes a rotated box) grown by a hair of 1e-9 of the sizes
/// involved, so that round-off, a million times smaller, cannot leave out a sample that the
/// exact test (Eq. (7.7)) keeps. Otherwise one run of every sample. The caller still applies
/// that exact test to each sample of a run, so the samples kept, their order and their
/// values are those of the loop over all samples. M^T is M's inverse only for a rotation: if
/// M^T M is off the identity by more than 1e-12 (a quaternion far from unit) every sample is
/// in the run, and so is every sample of a shape of at most four chunks (32 samples; a 2D
/// box has 16), where testing them all costs less than finding the runs.
///
/// When the bodies are turned relative to each other (some column of |M| sums to more than
/// 1.05), a chunk whose box meets the carried-back box is also carried forward: the box of M c + t
/// with half sizes |M| h (c, h the chunk box's centre and half sizes, |M| entrywise) must
/// meet boxB, grown by the same kind of hair. For every sample s of the chunk,
/// |M (s - c)| <= |M| h componentwise, so M s + t lies in that box: a chunk that fails
/// either test holds no sample the exact test keeps. The two boxes are the two families of
/// face axes of the separating-axis test of the chunk box against boxB; when the bodies are
/// turned relative to each other each one alone is loose (the axis box of a turned box),
/// and together they leave out most of the chunks that one lets through.
template <int D>
class NearSampleRuns {
 public:
  [[gnu::always_inline]] NearSampleRuns(const Shape<D>& owner, const Aabb<D>& boxB, const Mat<D>& M,
                                        const Vec<D>& t, bool cullByBounds)
      : count_(owner.surfaceSamples().size()), chunks_(cullByBounds ? owner.sampleChunks() : nullptr) {
    if (chunks_ != nullptr && !(chunks_->sampleCount() == count_ && chunks_->chunks().size() > 4 &&
                                 carryBack(boxB, M, t))) {
      chunks_ = nullptr;
    }
  }

  /// The next run [first, last); false when there is none left.
  bool next(std::size_t& first, std::size_t& last) {
    if (chunks_ != nullptr) return nextRun(first, last);
    if (next_ > 0 || count_ == 0) return false;
    next_ = 1;
    first = 0;
    last = count_;
    visited_ = count_;
    return true;
  }

  /// The samples in no run so far (all of them left out, once next() has returned false).
  std::size_t skipped() const { return count_ - visited_; }

 private:
  /// The query box in the owner's frame; false when M is not a rotation or boxB is empty.
  [[gnu::noinline]] bool carryBack(const Aabb<D>& boxB, const Mat<D>& M, const Vec<D>& t) {
    if (boxB.isEmpty() || !((M.transpose() * M - Mat<D>::Identity()).cwiseAbs().maxCoeff() <= 1e-12)) return false;
    const Vec<D> centre = M.transpose() * Vec<D>(boxB.center() - t);
    const Vec<D> half = M.transpose().cwiseAbs() * Vec<D>(0.5 * boxB.extent());
    const double hair =
        1e-9 * (1.0 + half.maxCoeff() + centre.cwiseAbs().maxCoeff() + t.cwiseAbs().maxCoeff());
    query_ = Aabb<D>{Vec<D>(centre.array() - half.array() - hair), Vec<D>(centre.array() + half.array() + hair)};
    // The forward test pays only when the carried-back box is loose: when some column of
    // |M| sums to more than 1.05, that box is more than 5 % wider than boxB's along that
    // axis of the owner (a cube's). Aligned bodies, as in a stack, skip it.
    forward_ = M.cwiseAbs().colwise().sum().maxCoeff() > 1.05;
    if (forward_) {
      M_ = M;
      absM_ = M.cwiseAbs();
      t_ = t;
      lowerB_ = boxB.lower;
      upperB_ = boxB.upper;
      scaleB_ = 1.0 + t.cwiseAbs().maxCoeff() + boxB.lower.cwiseAbs().maxCoeff() + boxB.upper.cwiseAbs().maxCoeff();
    }
    return true;
  }

  /// A group's or chunk's box `a` (owner frame) may hold a sample that lands in boxB.
  [[gnu::always_inline]] bool boxNear(const Aabb<D>& a) const { return a.overlaps(query_) && meetsForward(a); }

  /// The carried-forward test: the box of M a + t over a in `a` (owner frame) meets boxB,
  /// axis by axis; true without a test when forward_ is off.
  [[gnu::always_inline]] bool meetsForward(const Aabb<D>& a) const {
    if (!forward_) return true;
    double c[D], h[D], size = 0.0;
    for (int j = 0; j < D; ++j) {
      c[j] = 0.5 * (a.lower[j] + a.upper[j]);
      h[j] = 0.5 * (a.upper[j] - a.lower[j]);
      size = std::max(size, std::abs(c[j]) + h[j]);
    }
    const double hair = 1e-9 * (scaleB_ + D * size);
    for (int i = 0; i < D; ++i) {
      double centre = t_[i], half = hair;
      for (int j = 0; j < D; ++j) {
        centre += M_(i, j) * c[j];
        half += absM_(i, j) * h[j];
      }
      if (centre - half > upperB_[i] || centre + half < lowerB_[i]) return false;
    }
    return true;
  }

  [[gnu::noinline]] bool nextRun(std::size_t& first, std::size_t& last) {
    const std::vector<Aabb<D>>& chunks = chunks_->chunks();
    const std::vector<Aabb<D>>& groups = chunks_->groups();
    constexpr std::size_t G = SampleChunks<D>::groupSize;
    constexpr std::size_t C = SampleChunks<D>::chunkSize;
    while (next_ < chunks.size()) {
      if (next_ % G == 0 && !boxNear(groups[next_ / G])) {
        next_ += G;
        continue;
      }
      if (!boxNear(chunks[next_])) {
        ++next_;
        continue;
      }
      const std::size_t start = next_++;
      while (next_ < chunks.size() && (next_ % G != 0 || boxNear(groups[next_ / G])) && boxNear(chunks[next_])) ++next_;
      first = start * C;
      last = std::min(count_, next_ * C);
      visited_ += last - first;
      return true;
    }
    return false;
  }

  std::size_t count_ = 0;
  const SampleChunks<D>* chunks_ = nullptr;
  Aabb<D> query_;
  // Set by carryBack() only when forward_ is on, and read only then: a query of aligned
  // bodies (most of a stack's) does not pay to fill them.
  Mat<D> M_;     ///< owner frame -> boxB's frame (Eq. (7.2))
  Mat<D> absM_;  ///< |M|, entrywise
  Vec<D> t_;
  Vec<D> lowerB_, upperB_;  ///< boxB
  double scaleB_ = 1.0;  ///< the sizes of t and boxB, for the hair of meetsForward()
  bool forward_ = false;  ///< whether meetsForward() tests (the bodies are turned)
  std::size_t next_ = 0;
  std::size_t visited_ = 0;
};
// [near_samples]

// [sample_loop]
/// The work of one direction, as DetectionCounters counts it.
struct SampleWork {
  std::int64_t culled = 0;   ///< samples left out by the box test or by the runs
  std::int64_t queries = 0;  ///< phi evaluations
  std::int64_t found = 0;    ///< samples with phi < 0
};

/// The loop of one direction, the same for the full query (appendSamplesInside()) and the
/// lazy one (deepestApproachingInPair()): the samples of `owner` (its surfaceSamples()) in the runs that may reach
/// boxB (NearSampleRuns), in sample order, each carried into the penetrated body's frame
/// (Eq. (7.2)) and box-tested (Eq. (7.7)) before phi is asked; inside(k, xB, phi) receives
/// each sample k with phi < 0 (Eq. (7.1)), and the caller decides what to record.
/// One sample of a direction's loop: sample k (body-frame point s) carried into the
/// penetrated body's frame (Eq. (7.2)), box-tested (Eq. (7.7)), and given to inside(k, xB, phi)
/// when phi < 0 (Eq. (7.1)), with the work counted. The loop over every sample and the loop
/// over a candidate list (chapter 7, "Candidate lists") both test their samples here, so a
/// sample that both visit is computed by the same operations, with the same bits.
template <int D, class Inside>
[[gnu::always_inline]] inline void testSample(std::size_t k, const Vec<D>& s, const Shape<D>& shapeB,
                                              int penetratedIndex, const Aabb<D>& box, const Mat<D>& M,
                                              const Vec<D>& t, bool cullByBounds, std::int64_t& culled,
                                              std::int64_t& queries, std::int64_t& found, Inside& inside) {
  const Vec<D> xB = M * s + t;                // Eq. (7.2)
  if (cullByBounds && !box.contains(xB)) {    // Eq. (7.7)
    ++culled;
    return;
  }
  ++queries;
  const double phi = shapeB.signedDistance(xB);
  if (std::isnan(phi)) throwNanDistance<D>(shapeB, xB, penetratedIndex);
  if (!(phi < 0.0)) return;                   // Eq. (7.1)
  ++found;
  inside(k, xB, phi);
}

template <int D, class Inside>
[[gnu::always_inline]] inline void forEachSampleInside(const Shape<D>& owner, const std::vector<Vec<D>>& samples,
                                                       const Shape<D>& shapeB, int penetratedIndex,
                                                       const Aabb<D>& boxB, const Mat<D>& M, const Vec<D>& t,
                                                       bool cullByBounds, SampleWork& work, Inside&& inside) {
  if (samples.empty()) return;
  // Local copies, so that the calls in the loop cannot be assumed to change them and they
  // stay in registers (the same values, so the same bits).
  const Mat<D> Mk = M;
  const Vec<D> tk = t;
  const Aabb<D> box = boxB;
  std::int64_t culled = 0, queries = 0, found = 0;
  NearSampleRuns<D> runs(owner, box, Mk, tk, cullByBounds);
  for (std::size_t first = 0, last = 0; runs.next(first, last);) {
    for (std::size_t k = first; k < last; ++k) {
      testSample<D>(k, samples[k], shapeB, penetratedIndex, box, Mk, tk, cullByBounds, culled, queries, found, inside);
    }
  }
  work.culled += culled + static_cast<std::int64_t>(runs.skipped());
  work.queries += queries;
  work.found += found;
}
// [sample_loop]

/// Adds one direction's work to `counters` (when given): `transformed` samples went
/// through the loop.
inline void addSampleWork(DetectionCounters* counters, std::size_t transformed, const SampleWork& work) {
  if (counters == nullptr) return;
  counters->samplesTransformed += static_cast<std::int64_t>(transformed);
  counters->samplesCulled += work.culled;
  counters->phiQueries += work.queries;
  counters->interferenceSamples += work.found;
}

}  // namespace detail

// [surface_query]
/// The points of a body's surface the narrow phase tests against the other body's phi.
enum class SurfaceQuery {
  /// The fixed surface samples (chapter 7): 642 on a sphere, 48 on a disk by default.
  Samples,
  /// The samples and, for shapes that have it, the exact deepest point (Eq. (11.6)); a
  /// strictly convex shape (sphere, disk) is tested at its deepest point alone.
  DeepestPoint,
  /// DeepestPoint for the shapes with a curved surface (Shape::roundSurface(): sphere, disk,
  /// capsule, a 3D cylinder) and Samples for every other shape, so that a pair of boxes or
  /// meshes costs what it costs under Samples, bit for bit (chapter 12's default).
  RoundShapes,
};
// [surface_query]

/// Narrow-phase knobs. \ref ch07
struct NarrowPhaseSettings {
  /// Skip phi at samples outside the penetrated body's body-frame box (Eq. (7.7)).
  /// false queries phi at every sample: same result, to measure what culling saves.
  bool cullByBounds = true;
  /// Inflate that box by this much before culling (>= 0). 0 loses nothing when phi is
  /// exact, since phi > 0 outside the box. An approximate phi (a grid) can be slightly
  /// negative just outside the body's box; a margin as large as its error keeps those.
  double cullMargin = 0.0;
  /// Which surface points are tested (chapter 11): the samples only (GBF, the default), or
  /// also the exact deepest point of every shape that has the query (Shape::deepestPoint,
  /// the convex analytic primitives), which replaces the samples of a sphere or disk.
  SurfaceQuery surfaceQuery = SurfaceQuery::Samples;
  /// Candidate lists (chapter 7, "Candidate lists", Eq. (7.12)): the impulse loops keep, for
  /// each pair and direction, the samples that can still be inside while every sample has
  /// moved at most this fraction of the owner's sample radius, and ask only those until the
  /// bodies move farther (>= 0; 0: no lists, every ask runs the loop over all samples).
  /// Exact for any value: the samples found, their order and their bits are those of the
  /// full loop. It needs a Lipschitz bound of the penetrated body's phi
  /// (Shape::distanceLipschitz()); against a shape without one the full loop runs.
  double candidateReach = 0.002;
};

/// True when a pair of these shapes asks an exact deepest point under `settings`, so that its
/// tests go through pairInterference() rather than the lazy search over samples.
template <int D>
bool pairAsksDeepestPoint(const NarrowPhaseSettings& settings, const Shape<D>& a, const Shape<D>& b) {
  switch (settings.surfaceQuery) {
    case SurfaceQuery::Samples: return false;
    case SurfaceQuery::DeepestPoint: return true;
    case SurfaceQuery::RoundShapes: return a.roundSurface() || b.roundSurface();
  }
  return true;
}

namespace detail {

// [append_deepest_point]
/// Under SurfaceQuery::DeepestPoint: the owner's exact deepest point in `penetrated`
/// (Shape::deepestPoint), recorded like a sample (sampleIndex -2) when phi < 0 there.
/// Returns true when that point replaces the owner's samples (a sphere or disk).
template <int D>
bool appendDeepestPoint(const CollisionBody<D>& owner, int ownerIndex,
                        const CollisionBody<D>& penetrated, int penetratedIndex, const Mat<D>& M,
                        const Vec<D>& t, std::vector<InterferenceSample<D>>& out,
                        const NarrowPhaseSettings& settings, std::int64_t& queries,
                        std::int64_t& found) {
  if (!(settings.surfaceQuery == SurfaceQuery::DeepestPoint ||
        (settings.surfaceQuery == SurfaceQuery::RoundShapes && owner.shape->roundSurface()))) {
    return false;
  }
  const Shape<D>& shapeB = *penetrated.shape;
  Vec<D> p = Vec<D>::Zero();
  if (!owner.shape->deepestPoint(shapeB, M, t, p)) return false;
  const Vec<D> xB = M * p + t;  // Eq. (7.2)
  ++queries;
  const double phi = shapeB.signedDistance(xB);
  if (std::isnan(phi)) throwNanDistance<D>(shapeB, xB, penetratedIndex);
  if (phi < 0.0) {  // Eq. (7.1)
    ++found;
    InterferenceSample<D> sample;
    sample.point = owner.pose.toWorld(p);
    sample.depth = phi;
    sample.normal = penetrated.pose.directionToWorld(shapeB.normal(xB));  // Eq. (7.3)
    sample.owner = ownerIndex;
    sample.other = penetratedIndex;
    sample.sampleIndex = kDeepestPointSample;
    out.push_back(sample);
  }
  return owner.shape->deepestPointIsWholeContact();
}
// [append_deepest_point]

}  // namespace detail

// [samples_inside]
/// One direction of the interference test: every surface sample s of `owner` is carried
/// into the body frame of `penetrated` (Eq. (7.2)), culled by its body-frame box
/// (Eq. (7.7)), and recorded when phi_penetrated < 0 (Eq. (7.1)) with the world normal
/// of the penetrated body (Eq. (7.3)). Samples are appended to `out` in sample order.
/// The indices only label the records. \ref ch07
template <int D>
void appendSamplesInside(const CollisionBody<D>& owner, int ownerIndex,
                         const CollisionBody<D>& penetrated, int penetratedIndex,
                         std::vector<InterferenceSample<D>>& out,
                         const NarrowPhaseSettings& settings = {},
                         DetectionCounters* counters = nullptr) {
  if (owner.shape == nullptr || penetrated.shape == nullptr) {
    std::ostringstream msg;
    msg << "appendSamplesInside: body " << (owner.shape == nullptr ? ownerIndex : penetratedIndex)
        << " has no Shape (shape is null)";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(settings.cullMargin) || settings.cullMargin < 0.0) {
    std::ostringstream msg;
    msg << "appendSamplesInside: settings.cullMargin must be finite and >= 0, got "
        << settings.cullMargin;
    throw std::invalid_argument(msg.str());
  }
  detail::checkPose<D>(owner.pose, ownerIndex, "appendSamplesInside");
  detail::checkPose<D>(penetrated.pose, penetratedIndex, "appendSamplesInside");  // [samples_inside_core]
  const Shape<D>& shapeB = *penetrated.shape;
  const Aabb<D> boxB = shapeB.bounds().inflated(settings.cullMargin);
  // x_B = R_B^T (x_A + R_A s - x_B) = M s + t: one matrix for all samples (Eq. (7.2)).
  const Mat<D> RA = owner.poseRotation();
  const Mat<D> RB = penetrated.poseRotation();
  const Mat<D> M = RB.transpose() * RA;
  const Vec<D> t = RB.transpose() * Vec<D>(owner.pose.position - penetrated.pose.position);

  const std::vector<Vec<D>>& samples = owner.shape->surfaceSamples();
  detail::SampleWork work;
  const std::size_t sampleCount =
      detail::appendDeepestPoint<D>(owner, ownerIndex, penetrated, penetratedIndex, M, t, out,
                                    settings, work.queries, work.found)
          ? 0
          : samples.size();
  if (sampleCount > 0) {
    detail::forEachSampleInside<D>(*owner.shape, samples, shapeB, penetratedIndex, boxB, M, t, settings.cullByBounds, work,
                                   [&](std::size_t k, const Vec<D>& xB, double phi) {
                                     InterferenceSample<D> sample;
                                     sample.point = detail::poseToWorld<D>(owner.pose, RA, samples[k]);
                                     sample.depth = phi;
                                     sample.normal = detail::poseDirectionToWorld<D>(penetrated.pose, RB,
                                                                                     shapeB.normal(xB));  // Eq. (7.3)
                                     sample.owner = ownerIndex;
                                     sample.other = penetratedIndex;
                                     sample.sampleIndex = static_cast<int>(k);
                                     out.push_back(sample);
                                   });
  }
  detail::addSampleWork(counters, sampleCount, work);  // [samples_inside_core]
}
// [samples_inside]

// [pair_interference]
/// Both directions for one pair: the samples of bodies[pair.first] inside
/// bodies[pair.second], then those of bodies[pair.second] inside bodies[pair.first].
/// A pair can interfere in one direction only (a corner of B pushed into a face of A), so
/// neither half may be dropped. Throws std::invalid_argument for an index out of range or
/// a pair of one body with itself. \ref ch07
template <int D>
std::vector<InterferenceSample<D>> pairInterference(const std::vector<CollisionBody<D>>& bodies,
                                                    const BodyPair& pair,
                                                    const NarrowPhaseSettings& settings = {},
                                                    DetectionCounters* counters = nullptr) {
  const int n = static_cast<int>(bodies.size());
  if (pair.first < 0 || pair.first >= n || pair.second < 0 || pair.second >= n ||
      pair.first == pair.second) {
    std::ostringstream msg;
    msg << "pairInterference: pair (" << pair.first << ", " << pair.second
        << ") must name two different bodies among " << n;
    throw std::invalid_argument(msg.str());
  }
  std::vector<InterferenceSample<D>> out;
  const CollisionBody<D>& a = bodies[static_cast<std::size_t>(pair.first)];
  const CollisionBody<D>& b = bodies[static_cast<std::size_t>(pair.second)];
  appendSamplesInside<D>(a, pair.first, b, pair.second, out, settings, counters);
  appendSamplesInside<D>(b, pair.second, a, pair.first, out, settings, counters);
  if (counters != nullptr) ++counters->pairQueries;
  return out;
}
// [pair_interference]

// [sample_relative_velocity]
/// Relative velocity at an interference sample, u_rel = u_owner - u_other, each
/// u = v + omega x r with r measured from that body's centre of mass at its tested pose
/// (Eq. (7.4)), or at its pose at the start of the step when the views say so
/// (CollisionBody::arms, Eq. (8.22)); v and omega are the bodies' current velocities. \ref ch07
template <int D>
Vec<D> sampleRelativeVelocity(const InterferenceSample<D>& s,
                              const std::vector<CollisionBody<D>>& bodies) {
  const CollisionBody<D>& owner = bodies.at(static_cast<std::size_t>(s.owner));
  const CollisionBody<D>& other = bodies.at(static_cast<std::size_t>(s.other));
  checkCollisionBody<D>(owner, s.owner, "sampleRelativeVelocity");
  checkCollisionBody<D>(other, s.other, "sampleRelativeVelocity");
  const bool carried = s.isBodyPoint();
  return owner.body->pointVelocity(owner.leverArm(s.point, carried)) -
         other.body->pointVelocity(other.leverArm(s.point, carried));  // Eq. (7.4)
}

/// The normal part u_rel . N of the relative velocity: negative when the sample moves
/// deeper into the other body (approaching, Eq. (7.5)). N is the other body's normal, carried
/// like the lever arms (CollisionBody::carriedDirection()). \ref ch07
template <int D>
double normalRelativeVelocity(const InterferenceSample<D>& s,
                              const std::vector<CollisionBody<D>>& bodies) {
  const CollisionBody<D>& other = bodies.at(static_cast<std::size_t>(s.other));
  return sampleRelativeVelocity<D>(s, bodies).dot(other.carriedDirection(s.normal, s.isBodyPoint()));
}
// [sample_relative_velocity]

// [deepest_approaching]
/// The sample with the smallest phi among those that are approaching (u_rel . N < 0,
/// Eq. (7.5)); samples that separate or rest are ignored (Eq. (7.6)). Ties keep the first
/// in `samples`. Empty when no sample approaches. \ref ch07
///
/// Held samples (chapter 12, Eq. (12.6)): when the views carry load drops (the collision
/// stage), an approaching sample that interferes only because of the loads
/// (CollisionBody::interferesByLoadsAlone()) while a sample of the pair at least as deep
/// rests (does not approach) is held by that support and is not chosen.
template <int D>
std::optional<InterferenceSample<D>> deepestApproachingSample(
    const std::vector<InterferenceSample<D>>& samples, const std::vector<CollisionBody<D>>& bodies,
    DetectionCounters* counters = nullptr) {
  // The first resting sample in (depth, position) order: a sample after it in that order has a
  // resting one at least as deep (the order deepestApproachingInPair() visits them in).
  std::pair<double, std::size_t> firstResting{std::numeric_limits<double>::infinity(), samples.size()};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!(normalRelativeVelocity<D>(samples[i], bodies) < 0.0)) {
      firstResting = std::min(firstResting, std::pair<double, std::size_t>{samples[i].depth, i});
    }
  }
  std::optional<InterferenceSample<D>> best;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const InterferenceSample<D>& s = samples[i];
    if (!(normalRelativeVelocity<D>(s, bodies) < 0.0)) continue;  // Eq. (7.5)
    if (best && !(s.depth < best->depth)) continue;               // Eq. (7.6)
    if (firstResting < std::pair<double, std::size_t>{s.depth, i}) {  // Eq. (12.6)
      const CollisionBody<D>& owner = bodies[static_cast<std::size_t>(s.owner)];
      const CollisionBody<D>& other = bodies[static_cast<std::size_t>(s.other)];
      const Mat<D> Rother = other.poseRotation();
      if (owner.interferesByLoadsAlone(other, Rother, Vec<D>(Rother.transpose() * (s.point - other.pose.position)))) {
        if (counters != nullptr) ++counters->heldSamples;
        continue;
      }
    }
    best = s;
  }
  return best;
}
// [deepest_approaching]

// [deepest_approaching_lazy]
/// A sample found inside the other body, before its world point and normal are computed:
/// what deepestApproachingInPair() sorts by depth.
// [tied_landing]
/// Samples that land together (chapter 12, Eq. (12.7)): approaching samples whose depth is
/// within depthTolerance |phi| of the chosen sample's, with a normal within normalCosine of
/// its normal, share its impulse at their centre.
struct TiedLanding {
  double depthTolerance = 1e-6;
  double normalCosine = 0.99;
};
// [tied_landing]

template <int D>
struct InterferenceCandidate {
  Vec<D> inPenetrated = Vec<D>::Zero();  ///< the sample in the penetrated body's frame (x_B)
  double depth = 0.0;                    ///< phi there, < 0
  int order = 0;                         ///< position in pairInterference()'s sample order
  int sampleIndex = -1;                  ///< index in the owner's surfaceSamples()
  bool firstOwns = true;                 ///< owner is pair.first (else pair.second)
};

namespace detail {

// [candidate_list_make]
/// Makes `list` for the pose (M, t) while doing the direction's ordinary work: every sample
/// of the runs that may reach boxB grown by the reach (NearSampleRuns) is carried into the
/// penetrated frame; one that lands in the grown box (or any, without culling) gets phi, and
/// is listed when phi < L (reach + hair) (Eq. (7.12)); inside(k, xB, phi) receives, in sample
/// order, exactly the samples the full loop (forEachSampleInside()) would report.
template <int D, class Inside>
void makeCandidateList(CandidateList<D>& list, const Shape<D>& owner, const std::vector<Vec<D>>& samples,
                       double radius, const Shape<D>& shapeB, double lipschitz, int penetratedIndex,
                       const Aabb<D>& boxB, const Mat<D>& M, const Vec<D>& t,
                       const NarrowPhaseSettings& settings, SampleWork& work, Inside&& inside) {
  list.made = true;
  list.owner = &owner;
  list.penetrated = &shapeB;
  list.M = M;
  list.t = t;
  list.reach = settings.candidateReach * radius;
  list.hair = 1e-9 * (1.0 + radius + t.norm() + boxB.lower.norm() + boxB.upper.norm());
  list.samples.clear();
  const double keepBelow = lipschitz * (list.reach + list.hair);
  const Aabb<D> wide = boxB.inflated(list.reach + list.hair);
  const bool cull = settings.cullByBounds;
  std::int64_t culled = 0, queries = 0, found = 0;
  NearSampleRuns<D> runs(owner, wide, M, t, cull);
  for (std::size_t first = 0, last = 0; runs.next(first, last);) {
    for (std::size_t k = first; k < last; ++k) {
      const Vec<D> xB = M * samples[k] + t;  // Eq. (7.2)
      if (cull && !wide.contains(xB)) {
        ++culled;
        continue;
      }
      const bool asked = !cull || boxB.contains(xB);  // what the full loop asks (Eq. (7.7))
      const double phi = shapeB.signedDistance(xB);
      if (std::isnan(phi)) {
        if (asked) throwNanDistance<D>(shapeB, xB, penetratedIndex);
        list.samples.push_back(static_cast<int>(k));  // unknown: keep it, the full loop will ask
        continue;
      }
      if (phi < keepBelow) list.samples.push_back(static_cast<int>(k));
      if (!asked) {
        ++culled;
        continue;
      }
      ++queries;
      if (!(phi < 0.0)) continue;  // Eq. (7.1)
      ++found;
      inside(k, xB, phi);
    }
  }
  work.culled += culled + static_cast<std::int64_t>(runs.skipped());
  work.queries += queries;
  work.found += found;
}
// [candidate_list_make]

// [candidate_list_ask]
/// The direction's loop over the listed samples only: the same test and the same values,
/// sample for sample, as forEachSampleInside() gives them.
template <int D, class Inside>
void forEachListedSampleInside(const CandidateList<D>& list, const std::vector<Vec<D>>& samples,
                               const Shape<D>& shapeB, int penetratedIndex, const Aabb<D>& boxB,
                               const Mat<D>& M, const Vec<D>& t, bool cullByBounds, SampleWork& work,
                               Inside&& inside) {
  // Local copies, as in forEachSampleInside(): the same values, kept in registers.
  const Mat<D> Mk = M;
  const Vec<D> tk = t;
  const Aabb<D> box = boxB;
  std::int64_t culled = 0, queries = 0, found = 0;
  for (const int index : list.samples) {
    const std::size_t k = static_cast<std::size_t>(index);
    testSample<D>(k, samples[k], shapeB, penetratedIndex, box, Mk, tk, cullByBounds, culled, queries, found, inside);
  }
  work.culled += culled;
  work.queries += queries;
  work.found += found;
}
// [candidate_list_ask]

/// Appends the candidates of one direction, counting the same work as appendSamplesInside()
/// and with the same phi queries in the same order. With `list` (and candidate lists on, and
/// a Lipschitz bound for the penetrated shape, and sample chunks for the owner), the samples
/// come from the list while it covers the pose, and the list is remade when it does not.
template <int D>
void appendCandidatesInside(const CollisionBody<D>& owner, const Mat<D>& RA, const CollisionBody<D>& penetrated,
                            const Mat<D>& RB, int penetratedIndex, bool firstOwns,
                            std::vector<InterferenceCandidate<D>>& out,
                            const NarrowPhaseSettings& settings, DetectionCounters* counters,
                            CandidateList<D>* list = nullptr) {
  const Shape<D>& shapeB = *penetrated.shape;
  const Aabb<D> boxB = shapeB.bounds().inflated(settings.cullMargin);
  const Mat<D> M = RB.transpose() * RA;
  const Vec<D> t = RB.transpose() * Vec<D>(owner.pose.position - penetrated.pose.position);
  const std::vector<Vec<D>>& samples = owner.shape->surfaceSamples();
  SampleWork work;
  const auto record = [&](std::size_t k, const Vec<D>& xB, double phi) {
    out.push_back(InterferenceCandidate<D>{xB, phi, static_cast<int>(out.size()), static_cast<int>(k), firstOwns});
  };
  // [candidate_list_use]
  const SampleChunks<D>* chunks = owner.shape->sampleChunks();
  const double lipschitz = shapeB.distanceLipschitz();
  if (list != nullptr && settings.candidateReach > 0.0 && lipschitz > 0.0 && chunks != nullptr &&
      chunks->sampleCount() == samples.size()) {
    if (list->covers(*owner.shape, shapeB, M, t, chunks->radius())) {
      forEachListedSampleInside<D>(*list, samples, shapeB, penetratedIndex, boxB, M, t, settings.cullByBounds,
                                   work, record);
      addSampleWork(counters, list->samples.size(), work);
      if (counters != nullptr) ++counters->listedQueries;
    } else {
      makeCandidateList<D>(*list, *owner.shape, samples, chunks->radius(), shapeB, lipschitz, penetratedIndex, boxB,
                           M, t, settings, work, record);
      addSampleWork(counters, samples.size(), work);
      if (counters != nullptr) ++counters->candidateListsMade;
    }
    return;
  }
  // [candidate_list_use]
  forEachSampleInside<D>(*owner.shape, samples, shapeB, penetratedIndex, boxB, M, t, settings.cullByBounds, work,
                         record);
  addSampleWork(counters, samples.size(), work);
}

}  // namespace detail

/// deepestApproachingSample(pairInterference(bodies, pair)) without the normals and world
/// points of the samples it does not choose: the candidates are found as pairInterference()
/// finds them (same phi queries, same counters), ordered by depth with ties in sample
/// order, and the normal and the approach test (Eqs. (7.3)-(7.5)) are evaluated in that
/// order until the first sample that approaches. That sample is the deepest approaching
/// one, and among equally deep ones the first in sample order, exactly as Eq. (7.6) and
/// its tie rule pick it, with the same bits: each value is computed by the same operations.
/// `scratch` holds the candidates (reused across calls, so no allocation once it has grown).
/// `lists`, when given, are the pair's candidate lists (Eq. (7.12)): they are used while
/// they cover the bodies' relative pose and remade when they do not, with the same result
/// bit for bit; the caller keeps them from one ask of the pair to the next.
/// The bodies must have shapes and finite poses (the caller checks them once). \ref ch07
/// The overload on the pair's two views: `a` is body pair.first's, `b` body pair.second's
/// (the indices name the bodies in the sample and in errors only), so that a caller may ask
/// with a view that is not in a world's list, such as chapter 9's advanced body.
///
/// With `ties` (chapter 12, Eq. (12.7); the collision stage), the approaching samples whose
/// depth ties with the chosen one's (within ties->depthTolerance |phi|) and whose normal,
/// turned to its owner, lies within ties->normalCosine of its normal land with it: the
/// sample returned is at their centre (sampleIndex -1), with the chosen one's normal.
template <int D>
std::optional<InterferenceSample<D>> deepestApproachingInPair(
    const CollisionBody<D>& a, const CollisionBody<D>& b, const BodyPair& pair, const NarrowPhaseSettings& settings,
    DetectionCounters* counters, std::vector<InterferenceCandidate<D>>& scratch,
    PairCandidateLists<D>* lists = nullptr, const TiedLanding* ties = nullptr) {
  // pairInterference()'s checks, once for the pair.
  if (a.shape == nullptr || b.shape == nullptr || a.body == nullptr || b.body == nullptr) {
    std::ostringstream msg;
    msg << "deepestApproachingInPair: body " << (a.shape == nullptr || a.body == nullptr ? pair.first : pair.second)
        << " has no Shape or no RigidBody";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(settings.cullMargin) || settings.cullMargin < 0.0) {
    std::ostringstream msg;
    msg << "appendSamplesInside: settings.cullMargin must be finite and >= 0, got " << settings.cullMargin;
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(settings.candidateReach) || settings.candidateReach < 0.0) {
    std::ostringstream msg;
    msg << "deepestApproachingInPair: settings.candidateReach must be finite and >= 0, got "
        << settings.candidateReach;
    throw std::invalid_argument(msg.str());
  }
  detail::checkPose<D>(a.pose, pair.first, "appendSamplesInside");
  detail::checkPose<D>(b.pose, pair.second, "appendSamplesInside");
  // Each body's rotation matrix once per pair, kept by the view (RotationCache).
  const Mat<D> Ra = a.poseRotation();
  const Mat<D> Rb = b.poseRotation();
  scratch.clear();
  detail::appendCandidatesInside<D>(a, Ra, b, Rb, pair.second, true, scratch, settings, counters,
                                    lists != nullptr ? &lists->firstInSecond : nullptr);
  detail::appendCandidatesInside<D>(b, Rb, a, Ra, pair.first, false, scratch, settings, counters,
                                    lists != nullptr ? &lists->secondInFirst : nullptr);
  if (counters != nullptr) ++counters->pairQueries;
  // The approach test of candidate `index` (Eqs. (7.3)-(7.5)): the sample when it approaches
  // and is not held (Eq. (12.6)); candidates come in depth order, so a resting one seen
  // before is at least as deep.
  bool restingSeen = false;
  // Candidate `index` as a sample (Eq. (7.3)).
  const auto sampleOf = [&](std::size_t index) {
    const InterferenceCandidate<D>& c = scratch[index];
    const CollisionBody<D>& owner = c.firstOwns ? a : b;
    const CollisionBody<D>& other = c.firstOwns ? b : a;
    InterferenceSample<D> s;
    const Mat<D>& Rowner = c.firstOwns ? Ra : Rb;
    const Mat<D>& Rother = c.firstOwns ? Rb : Ra;
    s.point = detail::poseToWorld<D>(owner.pose, Rowner,
                                     owner.shape->surfaceSamples()[static_cast<std::size_t>(c.sampleIndex)]);
    s.depth = c.depth;
    s.normal = detail::poseDirectionToWorld<D>(other.pose, Rother, other.shape->normal(c.inPenetrated));  // Eq. (7.3)
    s.owner = c.firstOwns ? pair.first : pair.second;
    s.other = c.firstOwns ? pair.second : pair.first;
    s.sampleIndex = c.sampleIndex;
    return s;
  };
  // Whether sample s approaches (Eqs. (7.4), (7.5)).
  const auto approaches = [&](const InterferenceSample<D>& s) {
    const CollisionBody<D>& owner = s.owner == pair.first ? a : b;
    const CollisionBody<D>& other = s.owner == pair.first ? b : a;
    const Vec<D> u = owner.body->pointVelocity(owner.leverArm(s.point)) -
                     other.body->pointVelocity(other.leverArm(s.point));  // Eq. (7.4)
    return u.dot(other.carriedDirection(s.normal)) < 0.0;               // Eq. (7.5)
  };
  const auto approaching = [&](std::size_t index) -> std::optional<InterferenceSample<D>> {
    const InterferenceCandidate<D>& c = scratch[index];
    const CollisionBody<D>& owner = c.firstOwns ? a : b;
    const CollisionBody<D>& other = c.firstOwns ? b : a;
    const Mat<D>& Rother = c.firstOwns ? Rb : Ra;
    const InterferenceSample<D> s = sampleOf(index);
    if (!approaches(s)) {
      restingSeen = true;
      return std::nullopt;
    }
    // Held (Eq. (12.6)): a deeper sample rests and this one interferes by the loads alone (its
    // point in the other's frame computed as deepestApproachingSample() computes it).
    if (restingSeen &&
        owner.interferesByLoadsAlone(other, Rother, Vec<D>(Rother.transpose() * (s.point - other.pose.position)))) {
      if (counters != nullptr) ++counters->heldSamples;
      return std::nullopt;
    }
    return s;
  };
  const std::size_t count = scratch.size();
  if (count == 0) return std::nullopt;
  // [tied_landing_lazy]
  // The chosen candidate `index`, sample s, with the candidates that tie with it (Eq. (12.7)).
  // The members are summed in the candidates' order, which is pairInterference()'s sample
  // order, as tiedLandingPoint() sums them: the same centre, bit for bit, from either.
  const auto landing = [&](std::size_t index, InterferenceSample<D> s) {
    if (ties == nullptr || count < 2) return s;
    const double reach = ties->depthTolerance * std::abs(s.depth);
    Vec<D> sum = Vec<D>::Zero();
    int members = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (i == index) {
        sum += s.point;
        ++members;
        continue;
      }
      if (!(scratch[i].depth - s.depth <= reach)) continue;
      const InterferenceSample<D> t = sampleOf(i);
      const double sign = t.owner == s.owner ? 1.0 : -1.0;  // turned to s's owner
      if (!(sign * t.normal.dot(s.normal) >= ties->normalCosine)) continue;
      if (!approaches(t)) continue;  // Eq. (7.5)
      sum += t.point;
      ++members;
    }
    if (members > 1) {
      s.point = sum / static_cast<double>(members);  // Eq. (12.7)
      s.sampleIndex = -1;
    }
    return s;
  };
  // [tied_landing_lazy]
  // The first key, the smallest (depth, position), by one scan: in the impulse loops the
  // deepest candidate usually approaches, and then nothing needs ordering.
  std::size_t first = 0;
  for (std::size_t i = 1; i < count; ++i) {
    if (scratch[i].depth < scratch[first].depth) first = i;  // ties keep the earlier position
  }
  if (std::optional<InterferenceSample<D>> s = approaching(first)) return landing(first, *s);
  // The candidates by (depth, order): a stable sort by depth, since a candidate's position
  // in scratch is its order. Only (depth, position) keys are ordered, never the candidates
  // themselves; no depth is NaN (phi < 0) and positions are unique, so the keys are totally
  // ordered and any correct ordering of them visits the candidates in the same sequence.
  // A few keys (a 2D pair has a handful) are insertion-sorted on the stack; more are taken
  // one at a time from a min-heap (one buffer per thread, like scratch), so that a pair whose
  // deepest candidates approach costs the candidates evaluated rather than a full sort.
  // The few keys' two halves are left uninitialised: the sort writes entry i before it
  // reads it, and nothing reads past `count` (an array of pairs would be zeroed, 256 bytes,
  // on every query).
  using Key = std::pair<double, int>;
  constexpr std::size_t kFewKeys = 16;
  double fewDepth[kFewKeys];
  int fewPosition[kFewKeys];
  thread_local std::vector<Key> many;
  const auto later = [](const Key& x, const Key& y) { return y < x; };
  const bool useHeap = count > kFewKeys;
  if (useHeap) {
    many.clear();
    for (std::size_t i = 0; i < count; ++i) many.emplace_back(scratch[i].depth, static_cast<int>(i));
    std::make_heap(many.begin(), many.end(), later);
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      const double depth = scratch[i].depth;
      std::size_t j = i;
      for (; j > 0 && depth < fewDepth[j - 1]; --j) {
        fewDepth[j] = fewDepth[j - 1];
        fewPosition[j] = fewPosition[j - 1];
      }
      fewDepth[j] = depth;
      fewPosition[j] = static_cast<int>(i);
    }
  }
  // The rest in key order; the first key comes first in it and was tested above.
  for (std::size_t next = 0; next < count; ++next) {
    std::size_t index = 0;
    if (useHeap) {
      std::pop_heap(many.begin(), many.end() - static_cast<std::ptrdiff_t>(next), later);
      index = static_cast<std::size_t>(many[count - 1 - next].second);
    } else {
      index = static_cast<std::size_t>(fewPosition[next]);
    }
    if (next == 0) continue;  // index == first: keys are unique, so the smallest is the scan's
    if (std::optional<InterferenceSample<D>> s = approaching(index)) return landing(index, *s);
  }
  return std::nullopt;
}

/// The pair's views taken from `bodies` (the form the impulse loops use). Throws
/// std::invalid_argument unless the pair names two different bodies of the list.
template <int D>
std::optional<InterferenceSample<D>> deepestApproachingInPair(
    const std::vector<CollisionBody<D>>& bodies, const BodyPair& pair, const NarrowPhaseSettings& settings,
    DetectionCounters* counters, std::vector<InterferenceCandidate<D>>& scratch,
    PairCandidateLists<D>* lists = nullptr, const TiedLanding* ties = nullptr) {
  const int n = static_cast<int>(bodies.size());
  if (pair.first < 0 || pair.first >= n || pair.second < 0 || pair.second >= n || pair.first == pair.second) {
    std::ostringstream msg;
    msg << "deepestApproachingInPair: pair (" << pair.first << ", " << pair.second
        << ") must name two different bodies among " << n;
    throw std::invalid_argument(msg.str());
  }
  return deepestApproachingInPair<D>(bodies[static_cast<std::size_t>(pair.first)],
                                     bodies[static_cast<std::size_t>(pair.second)], pair, settings, counters,
                                     scratch, lists, ties);
}
// [deepest_approaching_lazy]

// [pair_interference_listed]
/// pairInterference() through the pair's candidate lists (Eq. (7.12)): the same samples,
/// in the same order and with the same bits, written to `out` (cleared first), with the
/// phi queries of the lists instead of every sample's. The candidates are found as
/// deepestApproachingInPair() finds them (`scratch` holds them); each then gets its world
/// point and normal by the operations appendSamplesInside() uses, in the same order
/// (first's samples inside second, then second's inside first). It is what a rule needing
/// every sample (chapter 8's centre, Eq. (8.10)) asks when the step keeps lists; `lists`
/// may be null (the full loop, as pairInterference()). Surface samples only: under
/// SurfaceQuery::DeepestPoint the caller asks pairInterference().
template <int D>
void pairInterferenceListed(const std::vector<CollisionBody<D>>& bodies, const BodyPair& pair,
                            const NarrowPhaseSettings& settings, DetectionCounters* counters,
                            std::vector<InterferenceCandidate<D>>& scratch, std::vector<InterferenceSample<D>>& out,
                            PairCandidateLists<D>* lists = nullptr) {
  const int n = static_cast<int>(bodies.size());
  if (pair.first < 0 || pair.first >= n || pair.second < 0 || pair.second >= n || pair.first == pair.second) {
    std::ostringstream msg;
    msg << "pairInterferenceListed: pair (" << pair.first << ", " << pair.second
        << ") must name two different bodies among " << n;
    throw std::invalid_argument(msg.str());
  }
  const CollisionBody<D>& a = bodies[static_cast<std::size_t>(pair.first)];
  const CollisionBody<D>& b = bodies[static_cast<std::size_t>(pair.second)];
  if (a.shape == nullptr || b.shape == nullptr) {
    std::ostringstream msg;
    msg << "pairInterferenceListed: body " << (a.shape == nullptr ? pair.first : pair.second)
        << " has no Shape (shape is null)";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(settings.cullMargin) || settings.cullMargin < 0.0) {
    std::ostringstream msg;
    msg << "appendSamplesInside: settings.cullMargin must be finite and >= 0, got " << settings.cullMargin;
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(settings.candidateReach) || settings.candidateReach < 0.0) {
    std::ostringstream msg;
    msg << "pairInterferenceListed: settings.candidateReach must be finite and >= 0, got "
        << settings.candidateReach;
    throw std::invalid_argument(msg.str());
  }
  detail::checkPose<D>(a.pose, pair.first, "appendSamplesInside");
  detail::checkPose<D>(b.pose, pair.second, "appendSamplesInside");
  const Mat<D> Ra = a.poseRotation();
  const Mat<D> Rb = b.poseRotation();
  scratch.clear();
  detail::appendCandidatesInside<D>(a, Ra, b, Rb, pair.second, true, scratch, settings, counters,
                                    lists != nullptr ? &lists->firstInSecond : nullptr);
  detail::appendCandidatesInside<D>(b, Rb, a, Ra, pair.first, false, scratch, settings, counters,
                                    lists != nullptr ? &lists->secondInFirst : nullptr);
  if (counters != nullptr) ++counters->pairQueries;
  out.clear();
  for (const InterferenceCandidate<D>& c : scratch) {  // in pairInterference()'s order
    const CollisionBody<D>& owner = c.firstOwns ? a : b;
    const CollisionBody<D>& other = c.firstOwns ? b : a;
    InterferenceSample<D> s;
    s.point = detail::poseToWorld<D>(owner.pose, c.firstOwns ? Ra : Rb,
                                     owner.shape->surfaceSamples()[static_cast<std::size_t>(c.sampleIndex)]);
    s.depth = c.depth;
    s.normal = detail::poseDirectionToWorld<D>(other.pose, c.firstOwns ? Rb : Ra,
                                               other.shape->normal(c.inPenetrated));  // Eq. (7.3)
    s.owner = c.firstOwns ? pair.first : pair.second;
    s.other = c.firstOwns ? pair.second : pair.first;
    s.sampleIndex = c.sampleIndex;
    out.push_back(s);
  }
}
// [pair_interference_listed]

/// The samples of one pair that interfere, with the pair they belong to.
template <int D>
struct PairInterference {
  BodyPair pair;
  std::vector<InterferenceSample<D>> samples;
};

/// Both phases' settings.
struct DetectionSettings {
  BroadPhaseSettings broad;
  NarrowPhaseSettings narrow;
};

// [detect_interference]
/// The whole detection of a scene: sweep and prune at the views' poses, then the narrow
/// phase on every reported pair. Returns the pairs that have at least one interference
/// sample, in the broad phase's (i, j) order. \ref ch07
template <int D>
std::vector<PairInterference<D>> detectInterference(const std::vector<CollisionBody<D>>& bodies,
                                                    const DetectionSettings& settings = {},
                                                    DetectionCounters* counters = nullptr) {
  std::vector<PairInterference<D>> result;
  for (const BodyPair& pair : sweepAndPrune<D>(bodies, settings.broad, counters)) {
    std::vector<InterferenceSample<D>> samples =
        pairInterference<D>(bodies, pair, settings.narrow, counters);
    if (!samples.empty()) result.push_back({pair, std::move(samples)});
  }
  return result;
}
// [detect_interference]

// Compiled once, for D = 2 and 3, in the library (collision/instantiate_collision.cpp).
#define STACKBOOK_EXTERN_NARROW_PHASE(D)                                                        \
  extern template std::vector<InterferenceSample<D>> pairInterference<D>(                       \
      const std::vector<CollisionBody<D>>&, const BodyPair&, const NarrowPhaseSettings&,        \
      DetectionCounters*);                                                                      \
  extern template std::optional<InterferenceSample<D>> deepestApproachingSample<D>(             \
      const std::vector<InterferenceSample<D>>&, const std::vector<CollisionBody<D>>&, DetectionCounters*); \
  extern template std::vector<PairInterference<D>> detectInterference<D>(                       \
      const std::vector<CollisionBody<D>>&, const DetectionSettings&, DetectionCounters*);
STACKBOOK_EXTERN_NARROW_PHASE(2)
STACKBOOK_EXTERN_NARROW_PHASE(3)
#undef STACKBOOK_EXTERN_NARROW_PHASE

}  // namespace stackbook
