#pragma once
/// \file
/// \brief A recorded run (chapter 10): what each body looks like, and where it is at each
/// recorded frame. Every output (CSV, animated SVG, animated glTF, viewer page) is written
/// from a Recording, so the simulator records once and the writers never see the World.

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/geometry/surface_mesh.hpp"
#include "stackbook/body/integrate.hpp"
#include "stackbook/math/pose.hpp"
#include "stackbook/stepping/contact_recorder.hpp"
#include "stackbook/stepping/world.hpp"

namespace stackbook {

// [body_visual]
/// How one body is drawn: its name, its surface in the body frame (segments in 2D,
/// triangles in 3D) and an sRGB colour. The scene builder makes it from the shape's
/// description (chapter 10), since an SDF alone has no surface to draw.
template <int D>
struct BodyVisual {
  std::string name;
  SurfaceMesh<D> mesh;
  bool isStatic = false;
  std::array<double, 3> color{0.55, 0.6, 0.7};  ///< sRGB in [0, 1]
};
// [body_visual]

// [frame_energy]
/// The energy of the dynamic bodies of a world at one frame: kinetic (m v.v + omega.L)/2 and
/// potential -m g.x (Eq. (10.4)); static bodies contribute nothing.
struct FrameEnergy {
  double kinetic = 0.0;
  double potential = 0.0;
  double total() const { return kinetic + potential; }
};

template <int D>
FrameEnergy frameEnergy(const World<D>& world) {
  FrameEnergy e;
  for (const RigidBody<D>& b : world.bodies) {
    if (b.isStatic()) continue;
    e.kinetic += b.kineticEnergy();
    e.potential -= b.mass() * world.gravity.dot(b.position);  // U = -m g.x, Eq. (10.4)
  }
  return e;
}
// [frame_energy]
// [recorded_contact]
/// An impulse of the run (ContactRecord) with the step that applied it: `frame` is the
/// recorded frame that step leads to (the first frame at or after it), `time` the end of
/// the step. The impulses with frame f and time == times()[f] are those of the step that
/// reached frame f: the contacts the outputs draw at that frame.
struct RecordedContact {
  std::size_t frame = 0;
  double time = 0.0;
  ContactRecord contact;
};
// [recorded_contact]

// [recording]
/// Frames of a run: times[f], poses[f][i] and the world-frame velocities v and omega of
/// body i, and the world's energy at the frame. Static bodies are recorded like the others
/// (they may be placed anywhere; they simply do not move).
template <int D>
class Recording {
 public:
  explicit Recording(std::vector<BodyVisual<D>> visuals) : visuals_(std::move(visuals)) {}

  /// Append a frame at time t with every body's pose; the world must have one body per
  /// visual, and t must not go back in time.
  void record(double t, const World<D>& world) {
    if (world.bodies.size() != visuals_.size()) {
      throw std::invalid_argument("Recording::record: the world has " +
                                  std::to_string(world.bodies.size()) + " bodies but the recording " +
                                  std::to_string(visuals_.size()) + " visuals");
    }  // [record_frame]
    std::vector<Pose<D>> frame;
    std::vector<Vec<D>> v;
    std::vector<AngVec<D>> omega;
    frame.reserve(world.bodies.size());
    for (const RigidBody<D>& body : world.bodies) {
      frame.push_back(poseOf<D>(body));
      v.push_back(body.velocity);
      omega.push_back(body.angularVelocity);
    }
    recordPoses(t, std::move(frame));
    velocities_.back() = std::move(v);
    angularVelocities_.back() = std::move(omega);
    energies_.back() = frameEnergy<D>(world);
  }  // [record_frame]

  /// Append a frame at time t from the poses themselves (one per visual, in order): for
  /// recordings that do not come from a World, such as the output writers' tests.
  void recordPoses(double t, std::vector<Pose<D>> frame) {
    if (frame.size() != visuals_.size()) {
      throw std::invalid_argument("Recording::recordPoses: the frame has " +
                                  std::to_string(frame.size()) + " poses but the recording " +
                                  std::to_string(visuals_.size()) + " visuals");
    }
    if (std::isnan(t) || (!times_.empty() && t < times_.back())) {
      throw std::invalid_argument("Recording::record: time went back (or is NaN)");
    }
    times_.push_back(t);
    poses_.push_back(std::move(frame));
    velocities_.emplace_back(visuals_.size(), Vec<D>::Zero());
    angularVelocities_.emplace_back(visuals_.size(), AngVec<D>::Zero());
    energies_.emplace_back();
  }

  /// Append the impulses of the step that ended at time t; they belong to the next frame
  /// to be recorded (frameCount()). Empty unless the run records contacts.
  void recordContacts(double t, const std::vector<ContactRecord>& contacts) {
    for (const ContactRecord& c : contacts) contacts_.push_back(RecordedContact{times_.size(), t, c});
  }
  const std::vector<RecordedContact>& contacts() const { return contacts_; }

  const std::vector<BodyVisual<D>>& visuals() const { return visuals_; }
  const std::vector<double>& times() const { return times_; }
  /// poses()[f][i]: body i at frame f.
  const std::vector<std::vector<Pose<D>>>& poses() const { return poses_; }
  /// velocities()[f][i], angularVelocities()[f][i]: v and omega of body i at frame f, world
  /// frame (zero for frames recorded from poses alone).
  const std::vector<std::vector<Vec<D>>>& velocities() const { return velocities_; }
  const std::vector<std::vector<AngVec<D>>>& angularVelocities() const { return angularVelocities_; }
  /// energies()[f]: the world's energy at frame f (zero for frames recorded from poses alone).
  const std::vector<FrameEnergy>& energies() const { return energies_; }
  std::size_t frameCount() const { return times_.size(); }
  std::size_t bodyCount() const { return visuals_.size(); }

 private:
  std::vector<BodyVisual<D>> visuals_;
  std::vector<double> times_;
  std::vector<std::vector<Pose<D>>> poses_;
  std::vector<std::vector<Vec<D>>> velocities_;
  std::vector<std::vector<AngVec<D>>> angularVelocities_;
  std::vector<FrameEnergy> energies_;
  std::vector<RecordedContact> contacts_;
};
// [recording]

}  // namespace stackbook
