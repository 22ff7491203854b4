#pragma once
/// \file
/// \brief The trajectory of a recorded run as a CSV file, for analysis in any tool
/// (chapter 10).

#include <string>

#include "stackbook/output/recording.hpp"

namespace stackbook {

// [trajectory_csv]
/// Write the poses of every body at every recorded frame to `path` as CSV (RFC 4180,
/// comma-separated, LF line ends, one header line).
///
/// One row per body per frame, frames in time order and bodies in index order within a
/// frame. The columns are
///
/// | column  | 2D      | 3D                  | meaning                                             |
/// |---------|---------|---------------------|-----------------------------------------------------|
/// | 1       | `time`  | `time`              | the frame's time t in seconds                       |
/// | 2       | `body`  | `body`              | the body's index i (0-based, as in the scene)        |
/// | 3       | `name`  | `name`              | the body's name (quoted if it holds `,` `"` or a line end) |
/// | 4..     | `x,y`   | `x,y,z`             | position of the centre of mass, world frame          |
/// | next    | `angle` | `qw,qx,qy,qz`       | orientation: 2D angle in radians (counterclockwise), 3D unit quaternion w x y z |
/// | next    | `vx,vy` | `vx,vy,vz`          | velocity of the centre of mass, m/s, world frame     |
/// | last    | `omega` | `wx,wy,wz`          | angular velocity, rad/s, world frame (2D: counterclockwise) |
///
/// Every number is written as the shortest decimal that reads back as exactly the same
/// double (std::to_chars), so `strtod` of a field reproduces the recorded value bit for bit.
/// Throws std::runtime_error naming `path` if the file cannot be written.
template <int D>
void writeTrajectoryCsv(const Recording<D>& recording, const std::string& path);
// [trajectory_csv]

// [energy_csv]
/// Write the world's energy at every recorded frame to `path` as CSV: one header line
/// `time,kinetic,potential,total` and one row per frame (J; potential -m g.x of the dynamic
/// bodies, Eq. (10.4)), every number exact as in writeTrajectoryCsv. Throws
/// std::runtime_error naming `path` if the file cannot be written.
template <int D>
void writeEnergyCsv(const Recording<D>& recording, const std::string& path);
// [energy_csv]

}  // namespace stackbook
