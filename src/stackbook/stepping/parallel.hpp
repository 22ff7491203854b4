#pragma once
/// \file
/// \brief The step's threads (chapter 10): how many a step may use, and one parallel loop
/// over index ranges. The library takes its threads from TBB (Debian's libtbb-dev); this
/// header does not include TBB, so code that includes the step needs nothing more.

#include <cstddef>
#include <functional>

namespace stackbook {

// [parallel_settings]
/// How a step shares its work among threads. Every setting changes the time and never the
/// result: the step is bit for bit the same for any thread count (chapter 10, "Threads").
struct ParallelSettings {
  /// Threads a step may use (>= 0); 0 means all the machine's hardware threads.
  int threads = 0;
  /// A sweep with fewer pairs than this runs on one thread (the split costs more than it
  /// saves), as does a sweep whose pairs form one island, and a wave of the pass's levels
  /// (sweepLevelWaves()) with fewer pairs than this in all is swept level by level.
  int minPairs = 16;
  /// Per-body loops (stage views, velocity and position updates) hand each thread at
  /// least this many bodies.
  int bodiesPerTask = 256;
  /// Under PairOrder::Colours, a colour of at least minPairs pairs is cut into this many
  /// runs per thread, so that a thread that finishes early takes another run (>= 1).
  int runsPerThread = 4;
  /// The contact graph's pair tests (worldContactGraph()) hand each thread at least this many
  /// pairs, so that a small world builds its graph on one thread: waking a second thread
  /// costs more than the tests of a few dozen pairs.
  int graphPairsPerTask = 64;
};
// [parallel_settings]

/// The number of threads `requested` means: itself if >= 1, else the hardware threads (>= 1).
int resolvedThreadCount(int requested);

/// Calls body(begin, end) over consecutive ranges that cover [0, count), each at least
/// `grain` long (but the last), on up to `threads` threads (resolvedThreadCount()). With
/// one thread, or count <= grain, it is one call body(0, count) on the calling thread.
/// body must not throw; ranges run in any order, so body must only write what its own
/// indices own.
void parallelFor(int threads, std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t begin, std::size_t end)>& body);

}  // namespace stackbook
