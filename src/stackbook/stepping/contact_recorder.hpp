#pragma once
/// \file
/// \brief An optional record of every impulse a step applies (chapter 10, "Contacts as
/// output"): which stage applied it, between which bodies, where, along which normal, and
/// how large. The step writes to a recorder only when StepSettings::contactRecorder points
/// at one; with nullptr (the default) nothing is recorded and nothing else changes.

#include <array>
#include <cstddef>
#include <vector>

#include "stackbook/math/types.hpp"

namespace stackbook {

// [contact_record]
/// The stage of the step that applied an impulse.
enum class ContactStage {
  Collision,  ///< the collision stage (Eq. (8.1)), with the bodies' restitution
  Contact,    ///< the contact stage (Eq. (8.2)), with the restitution ramp (Eq. (8.5))
  Shock,      ///< a shock-propagation level sweep (chapter 9)
};

/// The name written to files: "collision", "contact" or "shock".
inline const char* contactStageName(ContactStage stage) {
  switch (stage) {
    case ContactStage::Collision: return "collision";
    case ContactStage::Contact: return "contact";
    case ContactStage::Shock: return "shock";
  }
  return "contact";
}

/// One applied impulse: +impulse on body `owner` at `point`, -impulse on body `other`
/// (applyPairImpulse()). `point` is the owner's sample at the poses the stage tested, and
/// `normal` the unit outward normal of `other` there (chapter 7), so impulse . normal >= 0
/// for a pushing impulse. D < 3 leaves the last components 0.
struct ContactRecord {
  ContactStage stage = ContactStage::Contact;
  int owner = -1;
  int other = -1;
  std::array<double, 3> point{0.0, 0.0, 0.0};
  std::array<double, 3> normal{0.0, 0.0, 0.0};
  std::array<double, 3> impulse{0.0, 0.0, 0.0};
};
// [contact_record]

// [contact_recorder]
/// The impulses applied since the last clear(), in the order the step applied them.
class ContactRecorder {
 public:
  template <int D>
  void record(ContactStage stage, int owner, int other, const Vec<D>& point, const Vec<D>& normal,
              const Vec<D>& impulse) {
    ContactRecord r;
    r.stage = stage;
    r.owner = owner;
    r.other = other;
    for (int k = 0; k < D; ++k) {
      const auto c = static_cast<std::size_t>(k);
      r.point[c] = point[k];
      r.normal[c] = normal[k];
      r.impulse[c] = impulse[k];
    }
    records_.push_back(r);
  }

  /// Append a record as it is (to merge the recorders of islands run on several threads,
  /// chapter 10).
  void add(const ContactRecord& r) { records_.push_back(r); }

  const std::vector<ContactRecord>& records() const { return records_; }
  std::size_t size() const { return records_.size(); }
  void clear() { records_.clear(); }

 private:
  std::vector<ContactRecord> records_;
};
// [contact_recorder]

}  // namespace stackbook
