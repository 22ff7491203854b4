// Explicit instantiation of the dimension-generic templates for D = 2 and D = 3.
// Nothing here is called; it makes the compiler check every template in both
// dimensions, so a 3D-only assumption cannot hide in code no 2D test reaches.

#include "stackbook/body/integrate.hpp"
#include "stackbook/body/rigid_body.hpp"
#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/impulse/collision_matrix.hpp"
#include "stackbook/impulse/frictional_impulse.hpp"
#include "stackbook/impulse/frictionless_impulse.hpp"
#include "stackbook/geometry/shape.hpp"
#include "stackbook/geometry/surface_mesh.hpp"
#include "stackbook/math/pose.hpp"

namespace stackbook {

template struct RigidBody<2>;
template struct RigidBody<3>;
template struct Pose<2>;
template struct Pose<3>;
template struct Aabb<2>;
template struct Aabb<3>;
template struct SurfaceMesh<2>;
template struct SurfaceMesh<3>;

#define STACKBOOK_INSTANTIATE_IMPULSE(D)                                                     \
  template RigidBody<D> makeDynamicBody<D>(double, const AngVec<D>&);                        \
  template Mat<D> collisionMatrix<D>(const RigidBody<D>&, const Vec<D>&);                    \
  template Mat<D> pairCollisionMatrix<D>(const RigidBody<D>&, const Vec<D>&,                 \
                                         const RigidBody<D>&, const Vec<D>&);                \
  template Vec<D> relativeVelocity<D>(const RigidBody<D>&, const Vec<D>&,                    \
                                      const RigidBody<D>&, const Vec<D>&);                   \
  template ContactImpulse<D> frictionlessImpulse<D>(const Mat<D>&, const Vec<D>&,            \
                                                    const Vec<D>&, double, double);          \
  template ContactImpulse<D> frictionalImpulse<D>(const Mat<D>&, const Vec<D>&,              \
                                                  const Vec<D>&, double, double,             \
                                                  const FrictionSettings&);          \
  template void advanceVelocity<D>(RigidBody<D>&, double, const ExternalLoads<D>&);          \
  template void advancePosition<D>(RigidBody<D>&, double);                                   \
  template Pose<D> predictPose<D>(const RigidBody<D>&, double);                              \
  template Pose<D> predictPose<D>(const RigidBody<D>&, double, const ExternalLoads<D>&);    \
  template void advancePosition<D>(RigidBody<D>&, double, RotationUpdate);                   \
  template Pose<D> predictPose<D>(const RigidBody<D>&, double, RotationUpdate);              \
  template Pose<D> predictPose<D>(const RigidBody<D>&, double, const ExternalLoads<D>&,      \
                                  RotationUpdate);                                           \
  template MassProperties<D> computeMassProperties<D>(const SurfaceMesh<D>&, double,         \
                                                      const MassPropertySettings&);          \
  template PrincipalAxes<D> principalAxes<D>(const MassProperties<D>&,                       \
                                             const MassPropertySettings&);                   \
  template BodyFrame<D> moveToPrincipalFrame<D>(SurfaceMesh<D>&, double,                     \
                                                const MassPropertySettings&);                \
  template RigidBody<D> makeBodyFromMesh<D>(SurfaceMesh<D>&, double, const Pose<D>&,         \
                                            const MassPropertySettings&);

STACKBOOK_INSTANTIATE_IMPULSE(2)
STACKBOOK_INSTANTIATE_IMPULSE(3)

#undef STACKBOOK_INSTANTIATE_IMPULSE

}  // namespace stackbook
