#pragma once
// The piles of nonconvex bodies that peers_bench and pile_scaling_bench time once formed:
// the bundled 1000-body piles (scenes/pile_1000_2d_full.json and pile_1000_3d_full.json)
// with their arrays resized by overrides, so that every N uses the same body kinds.
#include <memory>
#include <string>
#include <vector>

#include "stackbook/peers/engine.hpp"
#include "stackbook/stepping/step_settings.hpp"

namespace peers {

/// A pile of nonconvex bodies read from a scene file (with --set style overrides), formed by
/// simulating until every body is slower than `settleSpeed` or `formSeconds` have passed.
/// A formed state is kept in `cacheDir` (empty: no cache) and reused by later runs.
struct PileSpec {
  std::string name;
  std::string description;
  std::string file;
  std::vector<std::string> overrides;
  double formSeconds = 3.0;
  double settleSpeed = 0.05;
  std::string cacheDir;
  /// Threads for the timed steps (-1: the scene's). Not part of the cache key: a step gives
  /// the same bits for any thread count (chapter 10), so the formed state is the same.
  int timingThreads = -1;
  /// The order of the timed steps' sweeps (chapter 10, "Colours"). Not part of the cache key
  /// either: the pile forms under the scene's own settings, the same for every order.
  stackbook::PairOrder timingPairOrder = stackbook::PairOrder::List;
};
std::unique_ptr<Engine> makeStackbookPile(const PileSpec& pile, stackbook::SolverPreset preset);

/// The folder of the bundled scenes.
std::string scenesDir();

/// A 2D pile of n bodies (n a multiple of 4, n/4 <= 250 or n = 50) of the bundled pile's kinds
/// (L, U, star, bone: n/4 each), laid out as that scene lays out its 1000 (rows of up to 25,
/// 0.75 m apart, one kind above the other), poured into its bin.
PileSpec pile2d(int n, const std::string& cacheDir);

/// A 3D pile of n in {8, 100, 1000} bodies of the bundled 3D pile's kinds (torus, cup, bone,
/// L: n/4 each), in layers of up to 10 x 5, poured into its bin.
PileSpec pile3d(int n, const std::string& cacheDir);

}  // namespace peers
