// The step's threads (chapter 10). See parallel.hpp.
#include "stackbook/stepping/parallel.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace stackbook {

int resolvedThreadCount(int requested) {
  if (requested >= 1) return requested;
  static const int hardware = std::max(1, tbb::info::default_concurrency());  // asked once
  return hardware;
}

namespace {

/// One TBB arena per thread count, made on first use and kept: an arena owns its worker
/// slots, so a step with `threads` = 2 never uses more than two, whatever the machine has.
tbb::task_arena& arenaFor(int threads) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
  if (!arena) arena = std::make_unique<tbb::task_arena>(threads);
  return *arena;
}

}  // namespace

void parallelFor(int threads, std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t, std::size_t)>& body) {
  const int n = resolvedThreadCount(threads);
  if (grain < 1) grain = 1;
  if (n <= 1 || count <= grain) {
    if (count > 0) body(0, count);
    return;
  }
  arenaFor(n).execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
  });
}

}  // namespace stackbook
