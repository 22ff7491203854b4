// Exercise 5.2 (reference solution): mass properties of a compound body by the
// parallel-axis theorem.
#include <sstream>
#include <stdexcept>

#include "stackbook/exercises/ex05_2_compound_body.hpp"

namespace stackbook::exercises {

template <int D>
MassProperties<D> combineMassProperties(const std::vector<CompoundPart<D>>& parts) {
  if (parts.empty()) {
    throw std::invalid_argument("combineMassProperties: there are no parts");
  }
  MassProperties<D> total;
  Vec<D> moment = Vec<D>::Zero();  // sum of m_i c_i
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const MassProperties<D>& p = parts[i].properties;
    if (!std::isfinite(p.mass) || !(p.mass > 0.0)) {
      std::ostringstream msg;
      msg << "combineMassProperties: part " << i << " has mass " << p.mass
          << "; every part needs a finite positive mass";
      throw std::invalid_argument(msg.str());
    }
    total.measure += p.measure;
    total.mass += p.mass;
    moment += p.mass * parts[i].placement.toWorld(p.centerOfMass);
  }
  total.centerOfMass = moment / total.mass;
  for (const CompoundPart<D>& part : parts) {
    const MassProperties<D>& p = part.properties;
    const AngMat<D> R = angularRotationMatrix<D>(part.placement.orientation);
    const Vec<D> d = part.placement.toWorld(p.centerOfMass) - total.centerOfMass;
    total.inertia += R * p.inertia * R.transpose();
    if constexpr (D == 3) {
      total.inertia += p.mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
    } else {
      total.inertia(0, 0) += p.mass * d.squaredNorm();
    }
  }
  return total;
}

template MassProperties<2> combineMassProperties<2>(const std::vector<CompoundPart<2>>&);
template MassProperties<3> combineMassProperties<3>(const std::vector<CompoundPart<3>>&);

}  // namespace stackbook::exercises
