#pragma once
/// \file
/// \brief Candidate lists kept from one stage to the next and from step to step (\ref ch07,
/// "Keeping lists between stages"). A list answers for two shapes at a relative pose
/// (CandidateList::covers()), whoever made it: a resting pair's lists made in one stage
/// still answer in the next one and in the next step, and need not be made again.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/collision/candidate_lists.hpp"
#include "stackbook/geometry/shape.hpp"

namespace stackbook {

// [candidate_list_store]
/// The lists the last stage left, one entry per pair in sorted (i, j) order
/// (pairs[k] owns lists[k]: firstInSecond holds body i's samples in body j). A stage takes
/// them at its start and hands its own back at its end. Which list a pair gets changes the
/// work of its queries only, never their answers, so the store needs no rule for when a
/// list is still good: covers() decides that at every ask.
template <int D>
struct CandidateListStore {
  /// The world's shapes when the lists were kept. Holding them keeps them alive, so no other
  /// shape can be made at the address a list names (its owner and penetrated shapes).
  std::vector<std::shared_ptr<const Shape<D>>> shapes;
  std::vector<BodyPair> pairs;                 ///< sorted, no repeats
  std::vector<PairCandidateLists<D>> lists;    ///< lists[k] belongs to pairs[k]

  /// Keeps the lists only if they were kept with these very shapes; otherwise starts empty
  /// with them (a scene whose shapes were replaced between steps).
  void matchShapes(const std::vector<std::shared_ptr<const Shape<D>>>& worldShapes) {
    if (shapes == worldShapes) return;
    shapes = worldShapes;
    pairs.clear();
    lists.clear();
  }

  /// Swaps the kept lists of pair {a, b} (in either order) with `lists`, so that
  /// lists.firstInSecond holds a's samples in b. Returns false, and swaps nothing, when the
  /// store has no entry for the pair. Swapping again gives them back.
  bool swapFor(int a, int b, PairCandidateLists<D>& swapped) {
    const BodyPair key{std::min(a, b), std::max(a, b)};
    const auto at = std::lower_bound(pairs.begin(), pairs.end(), key);
    if (at == pairs.end() || *at != key) return false;
    PairCandidateLists<D>& kept = this->lists[static_cast<std::size_t>(at - pairs.begin())];
    if (a < b) {
      std::swap(kept.firstInSecond, swapped.firstInSecond);
      std::swap(kept.secondInFirst, swapped.secondInFirst);
    } else {
      std::swap(kept.firstInSecond, swapped.secondInFirst);
      std::swap(kept.secondInFirst, swapped.firstInSecond);
    }
    return true;
  }

  /// Copies the kept lists of pair {a, b} (in either order) into `copied`, oriented as
  /// swapFor() orients them, and leaves the store as it is. Returns false, and copies nothing,
  /// when the store has no entry for the pair. For a query at a pose the stage's lists may not
  /// cover (the contact graph's advanced bodies): a list remade there stays with the copy, and
  /// the next stage still finds the one made at its own pose.
  bool copyFor(int a, int b, PairCandidateLists<D>& copied) const {
    const BodyPair key{std::min(a, b), std::max(a, b)};
    const auto at = std::lower_bound(pairs.begin(), pairs.end(), key);
    if (at == pairs.end() || *at != key) return false;
    const PairCandidateLists<D>& kept = this->lists[static_cast<std::size_t>(at - pairs.begin())];
    copied.firstInSecond = a < b ? kept.firstInSecond : kept.secondInFirst;  // reuses the copy's storage
    copied.secondInFirst = a < b ? kept.secondInFirst : kept.firstInSecond;
    return true;
  }
};
// [candidate_list_store]

}  // namespace stackbook
