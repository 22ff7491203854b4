// Chapter 9: graphs deep enough to overflow a recursive depth-first search.
//
// The work runs on a thread whose stack is 256 KiB. A recursive search needs one call frame
// per body along the deepest path, at least a few dozen bytes each: for a 100000-body chain
// several megabytes, far beyond 256 KiB, so a recursive implementation crashes this test.
// The iterative ones keep their stacks on the heap.
#include <doctest/doctest.h>

#include <pthread.h>

#include <cstddef>
#include <span>
#include <vector>

#include "stackbook/stacking/contact_graph.hpp"
#include "stackbook/stacking/contact_levels.hpp"
#include "stackbook/stacking/level_summary.hpp"
#include "stackbook/stacking/strongly_connected_components.hpp"

using namespace stackbook;

namespace {

constexpr int kDeepBodies = 100000;
constexpr std::size_t kSmallStackBytes = 256 * 1024;

struct DeepResults {
  ContactLevels chainLevels;
  ContactLevels chainDepth;
  LevelSummary ringSummary;
  ContactLevels ringLevels;
};

// A chain 0 -> 1 -> ... -> n-1 (a stack of n bodies), and the same chain closed into a
// ring by n-1 -> 0 (one cycle of n bodies: Tarjan's search goes n deep before it returns).
void* runDeepGraphs(void* out) {
  DeepResults& results = *static_cast<DeepResults*>(out);
  std::vector<ContactPair> edges;
  edges.reserve(kDeepBodies);
  for (int body = 1; body < kDeepBodies; ++body) edges.push_back({body - 1, body});
  const ContactGraph chain(kDeepBodies, edges);
  edges.push_back({kDeepBodies - 1, 0});
  const ContactGraph ring(kDeepBodies, edges);

  results.chainLevels = topologicalLevels(chain);
  results.ringLevels = topologicalLevels(ring);

  results.chainDepth = bfsDepthLevels(chain);
  results.ringSummary = summarizeLevels(ring, results.ringLevels);
  return nullptr;
}

/// Runs `work(arg)` on a new thread with a stack of `stackBytes`; false if it cannot start.
bool runOnSmallStack(void* (*work)(void*), void* arg, std::size_t stackBytes) {
  pthread_attr_t attributes;
  if (pthread_attr_init(&attributes) != 0) return false;
  bool ok = pthread_attr_setstacksize(&attributes, stackBytes) == 0;
  pthread_t thread;
  ok = ok && pthread_create(&thread, &attributes, work, arg) == 0;
  pthread_attr_destroy(&attributes);
  return ok && pthread_join(thread, nullptr) == 0;
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [deep_chain]
TEST_CASE("a 100000-body chain is processed without recursion") {
  DeepResults results;
  REQUIRE(runOnSmallStack(runDeepGraphs, &results, kSmallStackBytes));

  // The chain: body k at level k, resting on body k-1 (both layerings agree on a chain).
  REQUIRE(results.chainLevels.levelCount() == kDeepBodies);
  bool inOrder = true;
  for (int body = 0; body < kDeepBodies; ++body) {
    const std::size_t b = static_cast<std::size_t>(body);
    inOrder = inOrder && results.chainLevels.levelOfBody[b] == body &&
              results.chainDepth.levelOfBody[b] == body;
  }
  CHECK(inOrder);
  const std::span<const ContactPair> topPairs = results.chainLevels.pairs(kDeepBodies - 1);
  CHECK(std::vector<ContactPair>(topPairs.begin(), topPairs.end()) ==
        std::vector<ContactPair>{{kDeepBodies - 2, kDeepBodies - 1}});

  // The ring: one cycle of all the bodies, so one level that sweeps all n contacts.
  REQUIRE(results.ringLevels.levelCount() == 1);
  CHECK(results.ringLevels.pairs(0).size() == static_cast<std::size_t>(kDeepBodies));
  CHECK(results.ringSummary.cycleCount == 1);
  CHECK(results.ringSummary.largestCycle == static_cast<std::size_t>(kDeepBodies));
  // Speed is not asserted here (tests never time themselves); the cost is linear in
  // bodies + contacts by construction, and a recursive search would crash on this stack.
}
// [deep_chain]

}  // TEST_SUITE
