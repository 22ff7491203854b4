#pragma once
/// \file
/// \brief Every impulse of a recorded run as a CSV file (chapter 10, "Contacts as
/// output"): which step and stage applied it, between which bodies, where, along which
/// normal, and how large.

#include <string>

#include "stackbook/output/recording.hpp"

namespace stackbook {

// [contacts_csv]
/// Write recording.contacts() to `path` as CSV (RFC 4180, LF line ends, one header line):
/// one row per impulse, in the order the steps applied them. The columns are
///
/// | column | 2D | 3D | meaning |
/// |--------|----|----|---------|
/// | 1 | `frame` | `frame` | the recorded frame the step leads to (0-based, as in the trajectory file) |
/// | 2 | `time` | `time` | the end of the step that applied the impulse, in seconds |
/// | 3 | `stage` | `stage` | `collision`, `contact` or `shock` (a shock-propagation level sweep) |
/// | 4, 5 | `bodyA,nameA` | `bodyA,nameA` | the body that receives +j (index, name) |
/// | 6, 7 | `bodyB,nameB` | `bodyB,nameB` | the body that receives -j |
/// | 8.. | `x,y` | `x,y,z` | where: body A's surface sample, at the poses the stage tested |
/// | | `nx,ny` | `nx,ny,nz` | unit outward normal of body B there (j . n > 0 pushes A out of B) |
/// | | `jx,jy` | `jx,jy,jz` | the impulse j on body A, in N s |
///
/// In a shock-propagation sweep the lower body of the pair is frozen (chapter 9): there
/// the impulse changes only the upper body's momentum. Summed over the rows, the impulses
/// on a body that is never frozen equal m (v_end - v_start) - m g T. Numbers are the
/// shortest decimals that read back exactly. Throws std::runtime_error naming `path` if
/// the file cannot be written.
template <int D>
void writeContactsCsv(const Recording<D>& recording, const std::string& path);
// [contacts_csv]

}  // namespace stackbook
