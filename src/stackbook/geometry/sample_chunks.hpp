#pragma once
/// \file
/// \brief Boxes around runs of consecutive surface samples, so that the narrow phase can
/// skip the runs that cannot reach the other body's box (\ref ch07, "Skipping far samples").

#include <algorithm>
#include <cstddef>
#include <vector>

#include "stackbook/geometry/aabb.hpp"

namespace stackbook {

// [sample_chunks]
/// A two-level partition of a shape's samples *by index*: chunk c holds samples
/// c*chunkSize ... c*chunkSize + chunkSize - 1, group g holds chunks g*groupSize ...; each
/// has the box of its samples. Built once with the shape. Because the runs follow the sample
/// order, visiting the runs whose box overlaps a query box, in order, visits the samples in
/// sample order: a narrow phase that skips the other runs sees the same samples in the same
/// order as one that looks at all of them, provided the query box holds every sample that
/// could pass its exact test. Mesh vertices that are neighbours in index are usually
/// neighbours in space, which makes the runs' boxes small; that is what makes skipping pay,
/// never what makes it right.
template <int D>
class SampleChunks {
 public:
  static constexpr std::size_t chunkSize = 8;
  static constexpr std::size_t groupSize = 8;  ///< chunks per group (64 samples)

  SampleChunks() = default;
  explicit SampleChunks(const std::vector<Vec<D>>& samples) : count_(samples.size()) {
    for (const Vec<D>& s : samples) radius_ = std::max(radius_, s.norm());
    for (std::size_t first = 0; first < count_; first += chunkSize) {
      Aabb<D> box;
      for (std::size_t k = first; k < std::min(count_, first + chunkSize); ++k) box.extend(samples[k]);
      chunks_.push_back(box);
    }
    for (std::size_t first = 0; first < chunks_.size(); first += groupSize) {
      Aabb<D> box;
      for (std::size_t c = first; c < std::min(chunks_.size(), first + groupSize); ++c) box.extend(chunks_[c]);
      groups_.push_back(box);
    }
  }

  std::size_t sampleCount() const { return count_; }
  const std::vector<Aabb<D>>& chunks() const { return chunks_; }
  const std::vector<Aabb<D>>& groups() const { return groups_; }
  /// The largest distance of a sample from the body-frame origin, max |s|.
  double radius() const { return radius_; }

 private:
  std::size_t count_ = 0;
  double radius_ = 0.0;
  std::vector<Aabb<D>> chunks_;
  std::vector<Aabb<D>> groups_;
};
// [sample_chunks]

}  // namespace stackbook
