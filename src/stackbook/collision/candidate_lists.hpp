#pragma once
/// \file
/// \brief Candidate lists (\ref ch07, "Candidate lists"): for one direction of one pair, the
/// surface samples that can still be inside the other body while the two bodies' relative
/// pose stays close to the one the list was made at. The impulse loops ask the same pair
/// again after every impulse; between two asks the bodies move by dt times a change of
/// velocity, so the list answers most asks with the samples that matter only.

#include <cmath>
#include <vector>

#include "stackbook/geometry/aabb.hpp"
#include "stackbook/geometry/shape.hpp"

namespace stackbook {

// [candidate_list]
/// One direction of a pair: the samples of the owner that may fall inside the penetrated
/// body while every sample has moved, in the penetrated body's frame, at most `reach` from
/// where it was when the list was made (Eq. (7.12)).
template <int D>
struct CandidateList {
  bool made = false;
  const Shape<D>* owner = nullptr;       ///< the shapes it was made for: a list answers only for them
  const Shape<D>* penetrated = nullptr;
  Mat<D> M = Mat<D>::Identity();  ///< owner frame -> penetrated frame at making (Eq. (7.2))
  Vec<D> t = Vec<D>::Zero();
  double reach = 0.0;   ///< how far a sample may move before the list must be remade
  double hair = 0.0;    ///< room for round-off, 1e-9 of the sizes involved
  std::vector<int> samples;  ///< indices into the owner's surfaceSamples(), ascending

  /// How far any sample s (|s| <= radius) has moved since the list was made, at most:
  /// |(M' - M) s + (t' - t)| <= ||M' - M||_F radius + |t' - t| (Eq. (7.11)).
  double moved(const Mat<D>& Mnow, const Vec<D>& tnow, double radius) const {
    return (Mnow - M).norm() * radius + (tnow - t).norm();
  }

  /// True when the list still answers for these shapes at the pose (Mnow, tnow). The answer
  /// depends on the two shapes and their relative pose only, so a list handed to another pair
  /// of the same shapes is still right, and one handed to other shapes is remade.
  bool covers(const Shape<D>& ownerShape, const Shape<D>& penetratedShape, const Mat<D>& Mnow,
              const Vec<D>& tnow, double radius) const {
    return made && owner == &ownerShape && penetrated == &penetratedShape &&
           moved(Mnow, tnow, radius) + hair <= reach;
  }
};

/// Both directions of one pair: the first body's samples in the second, and back.
template <int D>
struct PairCandidateLists {
  CandidateList<D> firstInSecond;
  CandidateList<D> secondInFirst;
};
// [candidate_list]

}  // namespace stackbook
