#pragma once
/// \file
/// \brief The step's contact ledger: the total impulse each touching pair has exchanged
/// in the contact stage and the shock-propagation pass of one step, and the Coulomb cone
/// applied to that total (\ref ch08, "One cone per step", Eq. (8.13)).

#include <array>
#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <utility>

#include "stackbook/collision/broad_phase.hpp"
#include "stackbook/math/types.hpp"

namespace stackbook {

// [friction_cone_rule]
/// Which impulse Coulomb's cone bounds in the contact stage and the pass.
enum class FrictionConeRule {
  /// GBF: every impulse on its own, |j_t| <= mu j_n (Eq. (3.3)).
  EachImpulse,
  /// The pair's total contact impulse over the step (Eq. (8.13)): a sticking trial that
  /// one impulse alone would reject is taken when the total stays in the cone.
  StepTotal,
};
// [friction_cone_rule]

// [contact_ledger]
/// Per pair, the sum of the impulses applied to its lower-numbered body: the normal part
/// N = sum j . n and the tangential part T = sum (j - (j . n) n), D <= 3 components.
class ContactLedger {
 public:
  struct Total {
    double normal = 0.0;
    std::array<double, 3> tangential{0.0, 0.0, 0.0};
  };
  // [ledger_admits]
  /// Would adding impulse j on `owner` (along the owner's unit normal n) keep the pair's
  /// total in the cone of mu? Requires j . n > 0 (never a pulling impulse) and
  /// |P (T + j_t)| <= mu (N + j . n), P the projection on the plane normal to n (Eq. (8.13)).
  template <int D>
  bool admits(const BodyPair& pair, int owner, const Vec<D>& j, const Vec<D>& n, double mu) const {
    const double jn = j.dot(n);
    if (!(jn > 0.0)) return false;
    const auto [key, sign] = keyOf(pair, owner);
    Vec<D> t = sign * (j - jn * n);
    double normal = jn;
    if (const std::optional<Total> total = lookup(key)) {
      for (int k = 0; k < D; ++k) t[k] += total->tangential[static_cast<std::size_t>(k)];
      normal += total->normal;
    }
    t -= t.dot(n) * n;
    return t.norm() <= mu * normal;  // Eq. (8.13)
  }
    // [ledger_admits]
  /// Add impulse j on `owner`, along the owner's unit normal n, to the pair's total.
  template <int D>
  void record(const BodyPair& pair, int owner, const Vec<D>& j, const Vec<D>& n) {
    const auto [key, sign] = keyOf(pair, owner);
    const std::lock_guard<std::mutex> lock(mutex_);
    Total& total = totals_[key];
    const double jn = j.dot(n);
    const Vec<D> t = sign * (j - jn * n);
    total.normal += jn;
    for (int k = 0; k < D; ++k) total.tangential[static_cast<std::size_t>(k)] += t[k];
  }

  /// The pair's total, or nullptr if it exchanged no impulse.
  const Total* find(const BodyPair& pair) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = totals_.find(ordered(pair));
    return it == totals_.end() ? nullptr : &it->second;
  }
  std::size_t size() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return totals_.size();
  }
  void clear() {
    const std::lock_guard<std::mutex> lock(mutex_);
    totals_.clear();
  }

  // Islands of a sweep run on several threads (chapter 10) and record into one ledger:
  // each pair's entry is only ever touched by its own island, but the map's structure is
  // shared, so every access holds the mutex. The mutex itself is not copied.
  ContactLedger() = default;
  ContactLedger(const ContactLedger& o) : totals_(o.copyOfTotals()) {}
  ContactLedger& operator=(const ContactLedger& o) {
    if (this != &o) {
      std::map<BodyPair, Total> copy = o.copyOfTotals();
      const std::lock_guard<std::mutex> lock(mutex_);
      totals_ = std::move(copy);
    }
    return *this;
  }

 private:
  std::optional<Total> lookup(const BodyPair& key) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = totals_.find(key);
    if (it == totals_.end()) return std::nullopt;
    return it->second;
  }
  std::map<BodyPair, Total> copyOfTotals() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return totals_;
  }

  static BodyPair ordered(const BodyPair& p) {
    return p.first < p.second ? p : BodyPair{p.second, p.first};
  }
  /// The ordered key, and +1 if `owner` is its first body (the one totals are kept for).
  static std::pair<BodyPair, double> keyOf(const BodyPair& pair, int owner) {
    const BodyPair key = ordered(pair);
    return {key, owner == key.first ? 1.0 : -1.0};
  }

  std::map<BodyPair, Total> totals_;  // ordered: deterministic, no hashing
  mutable std::mutex mutex_;
};
// [contact_ledger]

}  // namespace stackbook
