#pragma once
/// \file
/// \brief Mass properties of the solid a damaged mesh stands for (\ref ch06, "Repairing
/// downloaded meshes"): the divergence theorem of chapter 5 needs a closed surface (with a
/// hole its answer depends on the apex, and two overlapping parts count their overlap
/// twice), so here the solid is the set {w(x) > 1/2} of the generalised winding number
/// (Eq. (6.9)), integrated cell by cell on a uniform grid over the mesh's bounding box.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "stackbook/geometry/mass_properties.hpp"
#include "stackbook/geometry/winding_number.hpp"

namespace stackbook {

// [winding_mass_properties]
/// Mass, centre of mass and inertia tensor about it of {x : w(x) > 1/2} at `density`
/// (Eq. (6.23)): the
/// bounding box is cut into cubic cells of side h = (largest extent) / cellsAcross, and
/// each cell whose centre has w > 1/2 counts as a uniform cube of mass density h^3 with
/// its own moment m h^2 / 6 about each axis. The error is O(h): a layer of cells about half
/// a cell thick along the surface is counted or not by where its centres fall, and near a
/// hole the test w > 1/2 is itself a guess. Cost: (cells) x (faces) solid angles.
/// Throws std::invalid_argument for cellsAcross < 2 or a mesh with no inside cell.
inline MassProperties<3> windingNumberMassProperties(const TriangleMesh& mesh, double density,
                                                     int cellsAcross) {
  if (cellsAcross < 2) {
    throw std::invalid_argument("windingNumberMassProperties: cellsAcross must be >= 2, got " +
                                std::to_string(cellsAcross));
  }
  const Aabb<3> box = mesh.bounds();
  const Vec3 extent = box.extent();
  const double h = extent.maxCoeff() / cellsAcross;
  std::array<int, 3> cells{};
  for (int k = 0; k < 3; ++k) cells[static_cast<std::size_t>(k)] = std::max(1, static_cast<int>(std::ceil(extent[k] / h - 1e-9)));
  // Cells centred on the box: the grid overhangs the box equally on both sides.
  Vec3 origin;
  for (int k = 0; k < 3; ++k) origin[k] = box.center()[k] - 0.5 * h * cells[static_cast<std::size_t>(k)];
  double count = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // sum of x x^T over the inside centres
  for (int i = 0; i < cells[0]; ++i) {
    for (int j = 0; j < cells[1]; ++j) {
      for (int k = 0; k < cells[2]; ++k) {
        const Vec3 x = origin + h * Vec3(i + 0.5, j + 0.5, k + 0.5);
        if (!(windingNumber<3>(mesh, x) > 0.5)) continue;  // Eq. (6.9)
        count += 1.0;
        first += x;
        second += x * x.transpose();
      }
    }
  }
  if (count == 0.0) {
    throw std::invalid_argument("windingNumberMassProperties: no cell centre has winding number > 1/2 "
                                "(the mesh encloses nothing at this resolution)");
  }
  const double cellMass = density * h * h * h;
  MassProperties<3> p;
  p.measure = count * h * h * h;
  p.mass = density * p.measure;
  p.centerOfMass = first / count;
  // Second moment about the centre: sum (x - c)(x - c)^T = sum x x^T - n c c^T.
  const Mat3 spread = cellMass * (second - count * p.centerOfMass * p.centerOfMass.transpose());
  p.inertia = spread.trace() * Mat3::Identity() - spread +
              Mat3::Identity() * (p.mass * h * h / 6.0);  // each cell's own moment
  return p;
}
// [winding_mass_properties]

}  // namespace stackbook
