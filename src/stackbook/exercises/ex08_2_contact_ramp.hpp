#pragma once
/// \file
/// \brief Exercise 8.2 (\ref ch08): another restitution schedule for the contact stage.
///
/// GBF's ramp e_k = -1 + k / N (Eq. (8.5)) removes the fraction k / N of the approach in
/// sweep k. Build the halving schedule e_k = -(1/2)^k for k = 1, ..., N - 1 and e_N = 0,
/// which removes half of what is left at first and stops the approach in the last sweep,
/// in the form StepSettings::contactRestitution expects (N values in [-1, 0]). Throw
/// std::invalid_argument for N < 1. Then measure it against GBF's ramp (chapter 8's cost
/// table): impulses, pair caps hit, and whether A1's box still stays still.

#include <vector>

namespace stackbook::exercises {

/// The halving schedule of `sweeps` contact restitutions, ending at exactly 0.
std::vector<double> halvingContactRamp(int sweeps);

}  // namespace stackbook::exercises
