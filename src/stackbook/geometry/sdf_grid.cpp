// Explicit instantiation of the signed-distance grid (sdf_grid.hpp, chapter 6) for D = 2
// and D = 3: the library compiles it once, and every other file that includes the header
// links against these instead of instantiating the build again.
#include "stackbook/geometry/sdf_grid.hpp"

namespace stackbook {

template class SdfGrid<2>;
template class SdfGrid<3>;
template SdfGrid<2> buildSdfGrid<2>(const SurfaceMesh<2>&, const SdfGridSettings&,
                                    const std::string&);
template SdfGrid<3> buildSdfGrid<3>(const SurfaceMesh<3>&, const SdfGridSettings&,
                                    const std::string&);
template SdfGrid<2> sampleSdfGrid<2>(const std::function<double(const Vec<2>&)>&,
                                     const Aabb<2>&, const SdfGridSettings&);
template SdfGrid<3> sampleSdfGrid<3>(const std::function<double(const Vec<3>&)>&,
                                     const Aabb<3>&, const SdfGridSettings&);
template void sdfGridLayout<2>(const Aabb<2>&, const SdfGridSettings&, Vec<2>&, double&,
                               std::array<int, 2>&);
template void sdfGridLayout<3>(const Aabb<3>&, const SdfGridSettings&, Vec<3>&, double&,
                               std::array<int, 3>&);

}  // namespace stackbook
