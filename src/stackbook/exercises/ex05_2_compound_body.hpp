#pragma once
/// \file
/// \brief Exercise 5.2: the mass properties of a body assembled from parts, by the
/// parallel-axis theorem (chapter 5, "Exercises").

#include <vector>

#include "stackbook/geometry/mass_properties.hpp"

namespace stackbook::exercises {

/// One part of a compound body: its mass properties, computed in its own frame, and the
/// pose of that frame in the compound's frame (a part point p sits at placement.toWorld(p)).
template <int D>
struct CompoundPart {
  MassProperties<D> properties;
  Pose<D> placement;
};

/// The mass properties of the union of the parts, in the compound's frame. The parts must
/// not overlap (overlapping material would be counted twice). Measures and masses add; the
/// centre of mass is the mass-weighted mean of the placed part centres; each part's inertia
/// is turned into the compound's axes (R I R^T) and moved to the compound's centre of mass
/// by the parallel-axis theorem, I += m (|d|^2 delta - d d^T) in 3D and I += m |d|^2 in 2D,
/// d the offset of the part's centre of mass from the compound's.
/// Throws std::invalid_argument when there are no parts or a part has a non-positive mass.
template <int D>
MassProperties<D> combineMassProperties(const std::vector<CompoundPart<D>>& parts);

}  // namespace stackbook::exercises
