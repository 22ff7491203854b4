// Exercise 12.1, reference solution: the lever rule (chapter 12, Eq. (12.8)).
#include "stackbook/exercises/ex12_1_lever_shares.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace stackbook {

std::vector<double> leverShares(double centre, const std::vector<double>& entries) {
  if (entries.empty()) throw std::invalid_argument("leverShares: no entries");
  if (!std::isfinite(centre)) throw std::invalid_argument("leverShares: the centre is not finite");
  // The nearest entry at or left of the centre, and at or right of it.
  std::size_t left = entries.size(), right = entries.size();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double x = entries[i];
    if (!std::isfinite(x)) throw std::invalid_argument("leverShares: an entry is not finite");
    if (x <= centre && (left == entries.size() || x > entries[left])) left = i;
    if (x >= centre && (right == entries.size() || x < entries[right])) right = i;
  }
  std::vector<double> shares(entries.size(), 0.0);
  if (left == entries.size() || right == entries.size()) {  // outside: the nearest entry takes it all
    const std::size_t nearest = left == entries.size() ? right : left;
    double count = 0.0;
    for (const double x : entries) count += x == entries[nearest] ? 1.0 : 0.0;
    for (std::size_t i = 0; i < entries.size(); ++i) shares[i] = entries[i] == entries[nearest] ? 1.0 / count : 0.0;
    return shares;
  }
  const double a = entries[left], b = entries[right];
  if (a == b) {  // the centre sits on entries at one place: they share equally
    double count = 0.0;
    for (const double x : entries) count += x == a ? 1.0 : 0.0;
    for (std::size_t i = 0; i < entries.size(); ++i) shares[i] = entries[i] == a ? 1.0 / count : 0.0;
    return shares;
  }
  shares[left] = (b - centre) / (b - a);  // Eq. (12.8): moments about the centre balance
  shares[right] = (centre - a) / (b - a);
  return shares;
}

}  // namespace stackbook
