#pragma once
/// \file
/// \brief A signed distance function on a uniform grid, built from a closed `SurfaceMesh<D>`
/// (\ref ch06): exact distance to the faces at every node, sign by generalised winding
/// number, multilinear interpolation between nodes, normals from the gradient, and a
/// documented extension outside the grid. GridShape wraps it into a `Shape<D>`.
///
/// Every knob lives in SdfGridSettings, with a default. The mesh distance with the same
/// sign rule, evaluated exactly at any point (no grid), is ExactMeshSdf: the reference the
/// grid's error is measured against.

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stackbook/geometry/face_bvh.hpp"
#include "stackbook/geometry/mesh_validation.hpp"
#include "stackbook/geometry/shape.hpp"
#include "stackbook/geometry/winding_number.hpp"

namespace stackbook {

/// How the grid decides inside from outside at its nodes (\ref ch06, "The sign").
enum class SdfSignMethod {
  /// Winding number at one node per sign region: nodes i, j that are grid neighbours with
  /// d_i + d_j > h cannot have the surface between them (Eq. (6.10)), so they share a sign;
  /// one winding number per connected region of such links decides the whole region.
  /// Needs a closed mesh (only then is w constant between surface crossings); for a
  /// damaged mesh built with validate = false, use WindingNumberPerNode.
  WindingNumberPerRegion,
  /// Winding number at every node: O(nodes x faces), the plain reference.
  WindingNumberPerNode,
};

/// How the gradient (and so the normal) is computed between nodes (\ref ch06, Eq. (6.13)).
enum class SdfGradientMethod {
  /// Central differences at the nodes (one-sided at the grid's edge), interpolated
  /// multilinearly: continuous across cells, error O(h^2) where phi is smooth.
  CentralDifferences,
  /// The exact gradient of the multilinear interpolant: constant along a cell's axis,
  /// discontinuous across cell faces, error O(h).
  InterpolantDerivative,
};

// [sdf_grid_settings]
/// The knobs of a signed-distance grid.
struct SdfGridSettings {
  /// Resolution: cells across the largest extent of the mesh's bounding box (>= 2).
  int cellsAcrossLargestExtent = 32;
  /// If > 0, the cell size h itself, overriding cellsAcrossLargestExtent.
  double cellSize = 0.0;
  /// Cells of padding on every side of the bounding box (>= 1). Two or more keep the
  /// central-difference stencil of every node within a cell of the surface inside the grid.
  int paddingCells = 3;
  SdfSignMethod sign = SdfSignMethod::WindingNumberPerRegion;
  SdfGradientMethod gradient = SdfGradientMethod::CentralDifferences;
  /// Faces per leaf of the bounding-volume hierarchy used for the distances.
  int bvhLeafSize = 4;
  /// Run validateMesh first (recommended: the sign needs a closed, oriented mesh).
  bool validate = true;
  /// Refuse grids with more nodes than this (8 bytes each).
  std::int64_t maxNodes = 64'000'000;
};
// [sdf_grid_settings]

/// What building the grid cost and found.
struct SdfBuildStats {
  std::int64_t nodes = 0;                ///< grid nodes
  std::uint64_t faceTests = 0;           ///< point-face distance evaluations
  std::int64_t windingEvaluations = 0;   ///< points where the full winding sum was taken
  std::int64_t signRegions = 0;          ///< connected sign regions (per-region method)
  double maxWindingDeviation = 0.0;      ///< max |w - round(w)| at those points
};

namespace detail {

/// Uniform random numbers from the splitmix64 generator, computed bit for bit the same on
/// every platform (the standard library's distributions are not specified that tightly).
class PortableUniform {
 public:
  explicit PortableUniform(std::uint64_t seed) : state_(seed) {}
  double operator()(double lo, double hi) {
    state_ += 0x9E3779B97F4A7C15ull;  // splitmix64
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

}  // namespace detail

// [sdf_grid_class]
/// Node values of a signed distance function on a uniform grid, with interpolation.
/// Node (i_0, ..., i_{D-1}) sits at origin + h (i_0, ..., i_{D-1}); values are stored with
/// i_0 varying fastest.
template <int D>
class SdfGrid {
 public:
  using Index = std::array<int, D>;

  SdfGrid() = default;
  /// A grid of given node values (i_0 fastest). Throws std::invalid_argument unless every
  /// axis has at least 2 nodes, the values match the counts and the cell size is finite
  /// and positive.
  SdfGrid(const Vec<D>& origin, double cellSize, const Index& nodeCounts,
          std::vector<double> values, SdfGradientMethod gradient);

  /// Interpolated phi at x (Eq. (6.11)); outside the grid box, the value at the nearest
  /// box point plus the distance to it (Eq. (6.14)).
  double value(const Vec<D>& x) const;
  /// Gradient of phi at x by the chosen method (Eq. (6.13)); outside the box, the
  /// gradient of the extension (Eq. (6.14)). Not normalised.
  Vec<D> gradient(const Vec<D>& x) const;
  /// Unit normal gradient/|gradient|. Where the gradient vanishes (on the medial axis, at
  /// the centre of a sphere) the other method's gradient, and failing that the last axis.
  Vec<D> normal(const Vec<D>& x) const;
  /// The gradient inside the grid box by the loop over the cell's corners of Eq. (6.13), as
  /// written in chapter 6. gradient() and normal() take a written-out form of the same sums
  /// for central differences, with the same bits; this is the form they are tested against.
  Vec<D> gradientByCorners(const Vec<D>& x, SdfGradientMethod method) const;

  /// The box the nodes span: [origin, origin + h (n - 1)].
  const Aabb<D>& box() const { return box_; }
  double cellSize() const { return h_; }
  const Index& nodeCounts() const { return n_; }
  std::int64_t nodeCount() const { return static_cast<std::int64_t>(values_.size()); }
  double nodeValue(const Index& i) const { return values_[linear(i)]; }
  Vec<D> nodePosition(const Index& i) const {
    Vec<D> p;
    for (int k = 0; k < D; ++k) p[k] = origin_[k] + h_ * i[k];
    return p;
  }
  const std::vector<double>& values() const { return values_; }
  /// Bytes of node storage (8 per node).
  std::size_t memoryBytes() const { return values_.size() * sizeof(double); }
  SdfGradientMethod gradientMethod() const { return gradient_; }
  /// A Lipschitz bound L of value(): |value(x) - value(y)| <= L |x - y| everywhere, from the
  /// node values (chapter 7, "Candidate lists"); 0 if a node value is not finite.
  double lipschitzBound() const { return lipschitz_; }
  /// Build statistics (zero for a grid made from values).
  const SdfBuildStats& stats() const { return stats_; }
  void setStats(const SdfBuildStats& stats) { stats_ = stats; }

 private:
  std::int64_t linear(const Index& i) const {
    std::int64_t index = 0;
    for (std::size_t k = D; k-- > 0;) index = index * n_[k] + i[k];
    return index;
  }
  /// Cell containing x (clamped into the grid) and the local coordinates t in [0, 1]^D.
  void locate(const Vec<D>& x, Index& cell, Vec<D>& t) const;
  double interpolate(const Vec<D>& x) const;
  Vec<D> gradientInside(const Vec<D>& x, SdfGradientMethod method) const;
  Vec<D> nodeGradient(const Index& i) const;
  /// d phi / d x_k at the node of linear index `node`, whose coordinate along axis k is `at`:
  /// the central difference, one-sided at the grid's edge (nodeGradient()'s component k).
  double nodeDifference(std::int64_t node, int at, int k) const {
    const std::size_t kk = static_cast<std::size_t>(k);
    const bool first = at == 0, last = at == n_[kk] - 1;
    const std::int64_t lo = first ? node : node - strides_[kk];
    const std::int64_t hi = last ? node : node + strides_[kk];
    return (values_[static_cast<std::size_t>(hi)] - values_[static_cast<std::size_t>(lo)]) /
           (first || last ? h_ : 2.0 * h_);
  }
  Vec<D> centralGradientInCell(const Index& cell, const Vec<D>& t) const;

  Vec<D> origin_ = Vec<D>::Zero();
  double h_ = 1.0;
  Index n_{};
  std::array<std::int64_t, D> strides_{};  ///< linear-index step along each axis
  Aabb<D> box_;
  std::vector<double> values_;
  SdfGradientMethod gradient_ = SdfGradientMethod::CentralDifferences;
  SdfBuildStats stats_;
  double lipschitz_ = 0.0;
};
// [sdf_grid_class]

/// Grid geometry for a region: node counts, origin and cell size from the settings
/// (resolution and padding), the region centred in the node box.
template <int D>
void sdfGridLayout(const Aabb<D>& region, const SdfGridSettings& settings, Vec<D>& origin,
                   double& cellSize, std::array<int, D>& nodeCounts);

/// Builds the grid of a closed mesh (\ref ch06): exact unsigned distance to the faces at
/// every node through a bounding-volume hierarchy, sign by winding number. `source` names
/// the mesh in error messages. Throws MeshError for a bad mesh (when settings.validate)
/// and std::invalid_argument for bad settings.
template <int D>
SdfGrid<D> buildSdfGrid(const SurfaceMesh<D>& mesh, const SdfGridSettings& settings = {},
                        const std::string& source = "mesh");

/// A grid sampled from any signed distance function over `region` (padded and resolved by
/// the settings as for a mesh): the grid of an analytic shape, with no tessellation error.
template <int D>
SdfGrid<D> sampleSdfGrid(const std::function<double(const Vec<D>&)>& phi, const Aabb<D>& region,
                         const SdfGridSettings& settings = {});

// [exact_mesh_sdf]
/// The exact signed distance to a closed mesh at any point, with no grid: nearest face by
/// the hierarchy, sign by the winding number (O(F) per query). The reference that the
/// grid's interpolation error is measured against, and a correct but slow phi for a body.
template <int D>
class ExactMeshSdf {
 public:
  explicit ExactMeshSdf(SurfaceMesh<D> mesh, int bvhLeafSize = 4)
      : mesh_(std::move(mesh)), bounds_(mesh_.bounds()), bvh_(mesh_, bvhLeafSize) {}
  double distance(const Vec<D>& x) const {
    const double d = bvh_.nearest(mesh_, x).distance();
    return insideByWindingNumber<D>(mesh_, x) ? -d : d;
  }
  /// (x - nearest point)/distance, flipped inside; at the surface itself the normal of
  /// the nearest face.
  Vec<D> normal(const Vec<D>& x) const {
    const NearestFace<D> nearest = bvh_.nearest(mesh_, x);
    const Vec<D> offset = x - nearest.closest.point;
    const double d = offset.norm();
    if (d > 0.0) return insideByWindingNumber<D>(mesh_, x) ? Vec<D>(-offset / d) : Vec<D>(offset / d);
    return faceNormal(static_cast<std::size_t>(nearest.face));
  }
  /// The mesh's box, computed once: the mesh cannot change after construction.
  Aabb<D> bounds() const { return bounds_; }
  std::string describe() const {
    std::ostringstream out;
    out << "exact distance to a mesh of " << mesh_.faces.size() << " faces";
    return out.str();
  }
  const SurfaceMesh<D>& mesh() const { return mesh_; }
  /// Unsigned distance only (no winding number): O(log F).
  double unsignedDistance(const Vec<D>& x) const { return bvh_.nearest(mesh_, x).distance(); }

 private:
  Vec<D> faceNormal(std::size_t f) const {
    const auto& face = mesh_.faces[f];
    const Vec<D> a = mesh_.vertices[face[0]];
    const Vec<D> b = mesh_.vertices[face[1]];
    if constexpr (D == 2) {
      return Vec2((b - a).y(), -(b - a).x()).normalized();
    } else {
      const Vec3 c = mesh_.vertices[face[2]];
      return (b - a).cross(c - a).normalized();
    }
  }
  SurfaceMesh<D> mesh_;
  Aabb<D> bounds_;
  FaceBvh<D> bvh_;
};
// [exact_mesh_sdf]

// [grid_shape]
/// A `Shape<D>` whose phi and normal come from a signed-distance grid of its mesh and whose
/// surface samples are the mesh vertices: GBF's representation of a nonconvex body.
template <int D>
class GridShape final : public Shape<D> {
 public:
  /// Validates the mesh (naming it `name` in errors) and builds its grid.
  GridShape(SurfaceMesh<D> mesh, std::string name, const SdfGridSettings& settings = {})
      : mesh_(std::move(mesh)), name_(std::move(name)), bounds_(mesh_.bounds()),
        grid_(buildSdfGrid<D>(mesh_, settings, name_)), chunks_(mesh_.vertices) {}
  double signedDistance(const Vec<D>& x) const override { return grid_.value(x); }
  Vec<D> normal(const Vec<D>& x) const override { return grid_.normal(x); }
  const std::vector<Vec<D>>& surfaceSamples() const override { return mesh_.vertices; }
  const SampleChunks<D>* sampleChunks() const override { return &chunks_; }
  double distanceLipschitz() const override { return grid_.lipschitzBound(); }
  /// The mesh's box, computed once at construction (the mesh is fixed from then on):
  /// the narrow phase asks for it on every query, and looping over every vertex each
  /// time made it a sixth of a formed pile's step.
  Aabb<D> bounds() const override { return bounds_; }
  std::string describe() const override {
    std::ostringstream out;
    out << name_ << " (grid";
    for (std::size_t k = 0; k < D; ++k) out << (k ? " x " : " ") << grid_.nodeCounts()[k];
    out << " nodes, h = " << grid_.cellSize() << ", " << mesh_.faces.size() << " faces, "
        << mesh_.vertices.size() << " samples)";
    return out.str();
  }
  const SdfGrid<D>& grid() const { return grid_; }
  const SurfaceMesh<D>& mesh() const { return mesh_; }
  const std::string& name() const { return name_; }

 private:
  SurfaceMesh<D> mesh_;
  std::string name_;
  Aabb<D> bounds_;
  SdfGrid<D> grid_;
  SampleChunks<D> chunks_;
};
// [grid_shape]

// --- Measuring a signed distance against a reference -----------------------------------

/// Errors of an approximate phi and normal against a reference over a point set.
struct SdfErrorStats {
  int points = 0;
  double maxError = 0.0;        ///< max |phi - phi_ref|
  double rmsError = 0.0;        ///< root mean square of phi - phi_ref
  double maxAngle = 0.0;        ///< max angle between the normals (radians)
  double rmsAngle = 0.0;        ///< root mean square angle (radians)
};

/// Compares phi and normals of `approx` against `reference` (both with distance(x)-like
/// callables) at the given points.
template <int D, class ApproxPhi, class ApproxNormal, class RefPhi, class RefNormal>
SdfErrorStats compareSdf(const std::vector<Vec<D>>& points, ApproxPhi approxPhi,
                         ApproxNormal approxNormal, RefPhi refPhi, RefNormal refNormal) {
  SdfErrorStats stats;
  double sumSquares = 0.0, sumAngles = 0.0;
  for (const Vec<D>& x : points) {
    const double e = std::abs(approxPhi(x) - refPhi(x));
    const Vec<D> na = approxNormal(x), nr = refNormal(x);
    // atan2(|a x b|, a.b) is accurate for small angles, unlike acos(a.b).
    double sine = 0.0;
    if constexpr (D == 2) {
      sine = std::abs(na.x() * nr.y() - na.y() * nr.x());
    } else {
      sine = na.cross(nr).norm();
    }
    const double angle = std::atan2(sine, na.dot(nr));
    stats.maxError = std::max(stats.maxError, e);
    stats.maxAngle = std::max(stats.maxAngle, angle);
    sumSquares += e * e;
    sumAngles += angle * angle;
    ++stats.points;
  }
  if (stats.points > 0) {
    stats.rmsError = std::sqrt(sumSquares / stats.points);
    stats.rmsAngle = std::sqrt(sumAngles / stats.points);
  }
  return stats;
}

/// `count` points drawn uniformly (portable seeded generator) from `box`, keeping only
/// those where lo <= phi(x) <= hi: a band around, inside or outside the surface.
template <int D>
std::vector<Vec<D>> sampleBand(const std::function<double(const Vec<D>&)>& phi,
                               const Aabb<D>& box, double lo, double hi, int count,
                               std::uint64_t seed = 1) {
  detail::PortableUniform uniform(seed);
  std::vector<Vec<D>> points;
  points.reserve(static_cast<std::size_t>(count));
  const std::int64_t maxTries = 10'000 * static_cast<std::int64_t>(count) + 1000;
  for (std::int64_t tries = 0; static_cast<int>(points.size()) < count; ++tries) {
    if (tries > maxTries) {
      throw std::invalid_argument("sampleBand: the band is (nearly) empty inside the box");
    }
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = uniform(box.lower[k], box.upper[k]);
    const double value = phi(x);
    if (value >= lo && value <= hi) points.push_back(x);
  }
  return points;
}

extern template class SdfGrid<2>;
extern template class SdfGrid<3>;
extern template SdfGrid<2> buildSdfGrid<2>(const SurfaceMesh<2>&, const SdfGridSettings&,
                                           const std::string&);
extern template SdfGrid<3> buildSdfGrid<3>(const SurfaceMesh<3>&, const SdfGridSettings&,
                                           const std::string&);
extern template SdfGrid<2> sampleSdfGrid<2>(const std::function<double(const Vec<2>&)>&,
                                            const Aabb<2>&, const SdfGridSettings&);
extern template SdfGrid<3> sampleSdfGrid<3>(const std::function<double(const Vec<3>&)>&,
                                            const Aabb<3>&, const SdfGridSettings&);

}  // namespace stackbook

#include "stackbook/geometry/sdf_grid_impl.hpp"
