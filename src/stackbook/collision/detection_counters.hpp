#pragma once
/// \file
/// \brief Counts of the work collision detection does, so that later chapters can report
/// what a scene costs in operations rather than in seconds (\ref ch07).

#include <cstdint>
#include <sstream>
#include <string>

namespace stackbook {

// [detection_counters]
/// Work done by the broad phase and the narrow phase. Every detection function takes an
/// optional `DetectionCounters*` and adds to it; nothing is reset behind the caller's
/// back, so one struct can sum a whole time step. \ref ch07
struct DetectionCounters {
  std::int64_t pairsTested = 0;         ///< broad phase: pairs whose boxes were compared
  std::int64_t pairsOverlapping = 0;    ///< broad phase: pairs whose boxes overlap (reported)
  std::int64_t pairQueries = 0;         ///< narrow phase: pairs examined (both directions)
  std::int64_t samplesTransformed = 0;  ///< surface samples carried into the other body's frame
  std::int64_t samplesCulled = 0;       ///< of those, rejected by the other body's box
  std::int64_t phiQueries = 0;          ///< signed-distance evaluations
  std::int64_t interferenceSamples = 0; ///< samples found inside the other body (phi < 0)
  std::int64_t candidateListsMade = 0;  ///< narrow phase: candidate lists made or remade (chapter 7)
  std::int64_t listedQueries = 0;       ///< narrow phase: directions answered from a candidate list
  std::int64_t heldSamples = 0;         ///< collision stage: approaching samples passed over as held (Eq. (12.6))

  /// Set every count back to zero.
  void reset() { *this = DetectionCounters{}; }

  /// Add another set of counts to this one.
  DetectionCounters& operator+=(const DetectionCounters& o) {
    pairsTested += o.pairsTested;
    pairsOverlapping += o.pairsOverlapping;
    pairQueries += o.pairQueries;
    samplesTransformed += o.samplesTransformed;
    samplesCulled += o.samplesCulled;
    phiQueries += o.phiQueries;
    interferenceSamples += o.interferenceSamples;
    candidateListsMade += o.candidateListsMade;
    listedQueries += o.listedQueries;
    heldSamples += o.heldSamples;
    return *this;
  }

  friend bool operator==(const DetectionCounters&, const DetectionCounters&) = default;

  /// One line for logs and reports, e.g. "broad phase: tested 12, overlapping 3 |
  /// narrow phase: pairs 3, transformed 48, culled 40, phi 8, inside 4".
  std::string summary() const {
    std::ostringstream out;
    out << "broad phase: tested " << pairsTested << ", overlapping " << pairsOverlapping
        << " | narrow phase: pairs " << pairQueries << ", transformed " << samplesTransformed
        << ", culled " << samplesCulled << ", phi " << phiQueries << ", inside "
        << interferenceSamples;
    return out.str();
  }
};
// [detection_counters]

}  // namespace stackbook
