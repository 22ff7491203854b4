// Chapter 8: a whole patch at once (Eqs. (8.16)-(8.19)). The sticking patch on a box that
// meets the ground along its bottom face: it stops the box in one impulse exactly when
// Coulomb's cone and the face can carry that impulse, and leaves the box to GBF's single
// point otherwise (sliding, tipping, bouncing, pulling); on a slope it never glues a block
// that should slide, and holds one that should not.
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "scenes.hpp"
#include "stackbook/impulse/patch_impulse.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

/// The four (2D: two) bottom corners of a unit box centred at (x, ..., 1/2), the corners
/// with x <= `right` only (a face that ends short of the box's own corner).
template <int D>
std::vector<Vec<D>> bottomCorners(double left = -0.5, double right = 0.5) {
  std::vector<Vec<D>> corners;
  if constexpr (D == 2) {
    corners = {Vec2(left, 0.0), Vec2(right, 0.0)};
  } else {
    corners = {Vec3(left, -0.5, 0.0), Vec3(right, -0.5, 0.0), Vec3(right, 0.5, 0.0), Vec3(left, 0.5, 0.0)};
  }
  return corners;
}

/// A unit box (mass 1, I = 1/6) resting on the ground with its centre at height 1/2, moving
/// at `slide` along x and `sink` downwards, spinning about the vertical at `spin` (3D).
template <int D>
RigidBody<D> movingBox(double slide, double sink, double spin = 0.0) {
  RigidBody<D> box = unitBox<D>();
  box.position = 0.5 * up<D>();
  box.velocity = slide * axis<D>(0) - sink * up<D>();
  if constexpr (D == 3) {
    box.setAngularVelocity(Vec3(0.0, 0.0, spin));
  }
  return box;
}

template <int D>
std::optional<PatchImpulse<D>> patchOn(const RigidBody<D>& box, double mu, double e = 0.0,
                                       const std::vector<Vec<D>>& patch = bottomCorners<D>()) {
  const RigidBody<D> ground = makeStaticBody<D>();
  return stickingPatchImpulse<D>(box, box.position, ground, Vec<D>::Zero(), patch, up<D>(), e, mu);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

// [patch_impulse_test]
TEST_CASE_TEMPLATE("A sticking patch stops a sliding box in one impulse when the cone and the face can carry it",
                   Dim, In2D, In3D) {
  // A unit box sliding at 0.3 m/s and sinking at 0.4 m/s, no spin. Stopping it takes J = -m v
  // through the centre of mass (Eq. (8.16)), so |J_t| / J_n = 0.3 / 0.4 = 0.75: the patch
  // sticks for mu = 0.8 and not for mu = 0.7 (Eq. (8.18)). J's line of action leaves the
  // centre (height 1/2) along (-0.3, 0.4) and meets the ground at x = 0.5 * 0.3 / 0.4 = 0.375,
  // the leading side of the face (Eq. (8.19)).
  constexpr int D = Dim::value;
  const RigidBody<D> box = movingBox<D>(0.3, 0.4);
  const std::optional<PatchImpulse<D>> stick = patchOn<D>(box, 0.8);
  REQUIRE(stick.has_value());
  CHECK((stick->J - Vec<D>(-box.velocity)).norm() < 1e-14);
  CHECK(stick->pressure[0] == doctest::Approx(0.375).epsilon(1e-12));
  CHECK(std::abs(stick->pressure[D - 1]) < 1e-14);
  RigidBody<D> after = box;
  after.applyImpulse(stick->point - after.position, stick->J);
  after.applyAngularImpulse(stick->L);
  CHECK(after.velocity.norm() < 1e-14);  // the whole twist is stopped
  CHECK(after.angularVelocity.norm() < 1e-14);
  CHECK(after.kineticEnergy() <= box.kineticEnergy());
  CHECK_FALSE(patchOn<D>(box, 0.7).has_value());  // outside the cone: the box slides
  // A face that ends at x = 0.3 (the box overhangs a ledge) cannot put the pressure at 0.375:
  // stopping the box there would need the ledge to pull on the overhanging part.
  CHECK_FALSE(patchOn<D>(box, 0.8, 0.0, bottomCorners<D>(-0.5, 0.3)).has_value());
  CHECK(patchOn<D>(box, 0.8, 0.0, bottomCorners<D>(-0.5, 0.4)).has_value());
}

TEST_CASE_TEMPLATE("A sticking patch leaves bouncing, separating and single-point contacts to GBF's impulse", Dim,
                   In2D, In3D) {
  constexpr int D = Dim::value;
  const RigidBody<D> box = movingBox<D>(0.0, 0.4);
  CHECK(patchOn<D>(box, 0.5).has_value());
  CHECK(patchOn<D>(box, 0.5, -0.5).has_value());        // a ramp's sweep: the patch stops it all the same
  CHECK_FALSE(patchOn<D>(box, 0.5, 0.5).has_value());   // restitution: a bounce is not a stick
  CHECK_FALSE(patchOn<D>(movingBox<D>(0.0, -0.4), 0.5).has_value());  // rising: it would pull
  CHECK_FALSE(patchOn<D>(box, 0.5, 0.0, {Vec<D>::Zero()}).has_value());  // one point is not a patch
  const RigidBody<D> wall = makeStaticBody<D>();
  CHECK_FALSE(stickingPatchImpulse<D>(wall, Vec<D>::Zero(), wall, Vec<D>::Zero(), bottomCorners<D>(), up<D>(), 0.0,
                                      0.5)
                  .has_value());  // two immovable bodies: nothing to stop
}

TEST_CASE("A sticking patch stops a spin about the normal only as far as friction on the face surely carries it") {
  // A unit cube sinking at 0.4 m/s and spinning at w about the vertical: stopping it takes
  // J = (0, 0, 0.4) at the face's middle and an angular impulse I w = w / 6 about the normal.
  // Eq. (8.19) guarantees (mu J_n - |J_t|) dmin^2 / dmax with the four corners at dmin = dmax
  // = sqrt(1/2) from the middle: with mu = 0.8 the patch sticks for w / 6 <= 0.32 sqrt(1/2),
  // w <= 1.3576.
  const double limit = 6.0 * 0.8 * 0.4 * std::sqrt(0.5);
  REQUIRE(limit == doctest::Approx(1.3576).epsilon(1e-4));
  const std::optional<PatchImpulse<3>> slow = patchOn<3>(movingBox<3>(0.0, 0.4, 0.98 * limit), 0.8);
  REQUIRE(slow.has_value());
  CHECK(slow->L[2] == doctest::Approx(-0.98 * limit / 6.0).epsilon(1e-12));
  CHECK_FALSE(patchOn<3>(movingBox<3>(0.0, 0.4, 1.02 * limit), 0.8).has_value());
}
// [patch_impulse_test]

TEST_CASE_TEMPLATE("Under the sticking patch a block that should slide slides as under GBF's rule, bit for bit",
                   Dim, In2D, In3D) {
  // A1/A2-style slope: 30 degrees with mu = 0.3 < tan 30: every patch would need a friction
  // ratio above mu, so each is refused and the step is GBF's, with the same bits.
  constexpr int D = Dim::value;
  InclineScene<D> gbf = makeIncline<D>(degrees(30.0), 0.3, 0.0);
  InclineScene<D> patch = gbf;
  StepSettings settings;
  StepSettings patchSettings = settings;
  patchSettings.impulsePoint.rule = ImpulsePointRule::StickingPatch;
  std::int64_t patches = 0;
  for (int n = 0; n < 500; ++n) {
    gbfStep<D>(gbf.world, settings);
    const StepCounters c = gbfStep<D>(patch.world, patchSettings);
    patches += c.collision.patchImpulses + c.contact.patchImpulses;
  }
  CHECK(patches == 0);
  CHECK(gbf.travelled() > 0.1);
  CHECK(patch.world.bodies[1].position == gbf.world.bodies[1].position);
  CHECK(patch.world.bodies[1].velocity == gbf.world.bodies[1].velocity);
}

TEST_CASE_TEMPLATE("Under the sticking patch a block that should hold on a slope holds", Dim, In2D, In3D) {
  // 20 degrees with mu = 0.5 > tan 20 = 0.364: the patch's ratio is tan 20 and it sticks;
  // the block stays where it was put for 2 s.
  constexpr int D = Dim::value;
  InclineScene<D> scene = makeIncline<D>(degrees(20.0), 0.5, 0.0);
  StepSettings settings;
  settings.impulsePoint.rule = ImpulsePointRule::StickingPatch;
  std::int64_t patches = 0;
  for (int n = 0; n < 2000; ++n) {
    const StepCounters c = gbfStep<D>(scene.world, settings);
    patches += c.collision.patchImpulses + c.contact.patchImpulses;
  }
  CHECK(patches > 0);
  CHECK(std::abs(scene.travelled()) < 1e-9);
  CHECK(std::abs(scene.speed()) < 1e-9);
}

}  // TEST_SUITE
