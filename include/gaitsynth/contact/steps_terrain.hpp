#pragma once
/// \file steps_terrain.hpp
/// Terrain with vertical drops: stairs and boxes (Wu & Popovic 2010 train the forward walk on
/// "terrain with vertical drops created with boxes" with heights uniform in [0, 0.2] m, and build
/// stair climbers for rises up to 0.4 m).
///
/// The ground is piecewise constant on a rectilinear grid of cells: x_edges (nx + 1 increasing
/// values; the first may be -inf and the last +inf), y_edges (ny + 1), and a height per cell;
/// cell (i, j) is [x_edges[i], x_edges[i+1]) x [y_edges[j], y_edges[j+1]). Outside the grid the
/// ground is at base_height. Treads are horizontal, so normal() is +z everywhere.
///
/// Penetration (used by penalty contact) treats the risers as vertical walls: a point below the
/// surface is pushed out along the shortest way to the surface, through the tread above it
/// (depth = height - z, normal +z) or a riser (the vertical face at a cell boundary, found by
/// walking along +-x and +-y; normal horizontal, or toward the riser's bottom edge when the point
/// is below the far ground too, as at the foot of a step). Along one axis (stairs) this is the
/// exact distance to the surface; on a grid of boxes diagonal neighbours are not searched. So a
/// toe that runs into a step is stopped by the riser instead of being lifted onto the tread by a
/// huge spring force, as a height-only query would do (the depth would jump by the rise height).
/// A point on a tread within its penetration depth of an edge is pushed partly sideways.
///
/// Constructors:
///   steps_terrain({{x0, h0}, {x1, h1}, ...}, base)   stairs/drops along x: height base for x < x0,
///                                                   h_k on [x_k, x_{k+1}), the last one to +inf
///   steps_terrain::stairs(x_start, run, rise, count)  a regular staircase (rise < 0: downstairs)
///   steps_terrain::boxes(origin, size, heights)      a regular grid of boxes (cells) of given size
///   random_boxes(options, seed)                      Wu & Popovic's random boxes
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/detail/uniform01.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

class steps_terrain {
 public:
  /// One step of a profile along x: the ground is at `height` from `x_start` on (until the next).
  struct step {
    double x_start;  ///< m
    double height;   ///< m
  };

  /// General form: cell (i, j) has height heights(i, j) (see the file comment).
  steps_terrain(std::vector<double> x_edges, std::vector<double> y_edges, Eigen::MatrixXd heights,
                double base_height = 0.0)
      : xe_(std::move(x_edges)),
        ye_(std::move(y_edges)),
        h_(std::move(heights)),
        base_(base_height) {
    validate();
    max_height_ = std::max(base_, h_.maxCoeff());
  }

  /// Stairs / drops along x (planar models need nothing else): height `base_height` for
  /// x < steps[0].x_start, steps[k].height on [x_start_k, x_start_{k+1}), the last to +inf.
  /// x_start must be finite and strictly increasing.
  explicit steps_terrain(const std::vector<step>& steps, double base_height = 0.0)
      : base_(base_height) {
    check_argument(!steps.empty(), "steps_terrain: the list of steps is empty");
    xe_.reserve(steps.size() + 1);
    h_.resize(static_cast<Eigen::Index>(steps.size()), 1);
    for (std::size_t k = 0; k < steps.size(); ++k) {
      check_argument(std::isfinite(steps[k].x_start), "steps_terrain: step ", k,
                     " x_start is not finite (", steps[k].x_start, ")");
      check_argument(std::isfinite(steps[k].height), "steps_terrain: step ", k,
                     " height is not finite (", steps[k].height, ")");
      xe_.push_back(steps[k].x_start);
      h_(static_cast<Eigen::Index>(k), 0) = steps[k].height;
    }
    xe_.push_back(std::numeric_limits<double>::infinity());
    ye_ = {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    validate();
    max_height_ = std::max(base_, h_.maxCoeff());
  }

  /// `count` steps of depth `run` and rise `rise` (m) starting at x_start from base_height; the
  /// last tread continues to +inf. A negative rise makes a downward staircase.
  static steps_terrain stairs(double x_start, double run, double rise, int count,
                              double base_height = 0.0) {
    check_argument(count >= 1, "steps_terrain::stairs: count must be >= 1, got ", count);
    check_positive(run, "steps_terrain::stairs: run");
    check_argument(std::isfinite(rise), "steps_terrain::stairs: rise must be finite, got ", rise);
    check_argument(std::isfinite(x_start), "steps_terrain::stairs: x_start must be finite, got ",
                   x_start);
    std::vector<step> s;
    s.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) s.push_back({x_start + k * run, base_height + (k + 1) * rise});
    return steps_terrain(s, base_height);
  }

  /// A regular grid of boxes: box (i, j) covers [origin + (i, j) .* size, origin + (i+1, j+1) .*
  /// size) with top heights(i, j); base_height elsewhere.
  static steps_terrain boxes(const Eigen::Vector2d& origin, const Eigen::Vector2d& size,
                             Eigen::MatrixXd heights, double base_height = 0.0) {
    check_argument(origin.allFinite(), "steps_terrain::boxes: origin must be finite, got (",
                   origin.transpose(), ")");
    check_positive(size.x(), "steps_terrain::boxes: size.x");
    check_positive(size.y(), "steps_terrain::boxes: size.y");
    check_argument(heights.rows() >= 1 && heights.cols() >= 1,
                   "steps_terrain::boxes: grid is empty (", heights.rows(), " x ", heights.cols(),
                   " boxes)");
    std::vector<double> xe(static_cast<std::size_t>(heights.rows()) + 1),
        ye(static_cast<std::size_t>(heights.cols()) + 1);
    for (std::size_t i = 0; i < xe.size(); ++i)
      xe[i] = origin.x() + static_cast<double>(i) * size.x();
    for (std::size_t j = 0; j < ye.size(); ++j)
      ye[j] = origin.y() + static_cast<double>(j) * size.y();
    return steps_terrain(std::move(xe), std::move(ye), std::move(heights), base_height);
  }

  double height(double x, double y) const { return cell_height(find(xe_, x), find(ye_, y)); }
  vec3 normal(double /*x*/, double /*y*/) const { return vec3::UnitZ(); }

  /// Nearest-face penetration (see the file comment). depth <= 0 means the point is not below the
  /// ground; then the normal is +z.
  surface_contact penetration(const vec3& p) const {
    const int i = find(xe_, p.x()), j = find(ye_, p.y());
    const double z = p.z();
    surface_contact c{cell_height(i, j) - z, vec3::UnitZ()};
    if (!(c.depth > 0.0)) return c;
    const int nx = num_x(), ny = num_y();
    // Walk along each horizontal axis over the cell boundaries; each riser between a near cell and
    // a far cell is the vertical segment [lo, hi] of their heights at that boundary, and its point
    // nearest to p is at height clamp(z, lo, hi) (the concave corner when the far ground is above
    // z too). Stop once the lateral distance alone exceeds the best exit, or past a boundary whose
    // far side is at or below z (everything further is farther).
    const auto riser = [&](double d, double h_near, double h_far, const vec3& out) {
      // d: lateral distance to the boundary; out: unit horizontal direction toward it.
      const double zc = std::clamp(z, std::min(h_near, h_far), std::max(h_near, h_far));
      const double dist = std::hypot(d, zc - z);
      if (dist < c.depth) {
        c.depth = dist;
        c.normal = dist > 0.0 ? vec3((d * out + (zc - z) * vec3::UnitZ()) / dist) : out;
      }
      return h_far <= z;  // stop walking
    };
    for (int k = i; k >= 0; --k) {  // -x: boundary xe_[k] between cells k-1 and k
      const double d = p.x() - xe_[k];
      if (!(d < c.depth)) break;
      if (riser(d, cell_height(k, j), cell_height(k - 1, j), -vec3::UnitX())) break;
    }
    for (int k = i + 1; k <= nx; ++k) {  // +x
      const double d = xe_[k] - p.x();
      if (!(d < c.depth)) break;
      if (riser(d, cell_height(k - 1, j), cell_height(k, j), vec3::UnitX())) break;
    }
    for (int k = j; k >= 0; --k) {  // -y
      const double d = p.y() - ye_[k];
      if (!(d < c.depth)) break;
      if (riser(d, cell_height(i, k), cell_height(i, k - 1), -vec3::UnitY())) break;
    }
    for (int k = j + 1; k <= ny; ++k) {  // +y
      const double d = ye_[k] - p.y();
      if (!(d < c.depth)) break;
      if (riser(d, cell_height(i, k - 1), cell_height(i, k), vec3::UnitY())) break;
    }
    return c;
  }

  double base_height() const { return base_; }
  /// The height bound over any disc: the highest tread (or the base).
  double max_height(double /*x*/, double /*y*/, double /*r*/) const { return max_height_; }
  const std::vector<double>& x_edges() const { return xe_; }
  const std::vector<double>& y_edges() const { return ye_; }
  const Eigen::MatrixXd& heights() const { return h_; }
  int num_x() const { return static_cast<int>(h_.rows()); }
  int num_y() const { return static_cast<int>(h_.cols()); }

 private:
  /// Cell index along one axis in [-1, n]: -1 before the first edge, n at or after the last.
  static int find(const std::vector<double>& e, double s) {
    return static_cast<int>(std::upper_bound(e.begin(), e.end(), s) - e.begin()) - 1;
  }
  double cell_height(int i, int j) const {
    if (i < 0 || j < 0 || i >= num_x() || j >= num_y()) return base_;
    return h_(i, j);
  }

  static void validate_edges(const std::vector<double>& e, const char* what) {
    for (std::size_t k = 0; k < e.size(); ++k) {
      const bool first = k == 0, last = k + 1 == e.size();
      const bool ok = std::isfinite(e[k]) || (first && e[k] < 0 && !std::isnan(e[k])) ||
                      (last && e[k] > 0 && !std::isnan(e[k]));
      check_argument(ok, "steps_terrain: ", what, "[", k, "] = ", e[k],
                     " must be finite (only the first may be -inf, the last +inf)");
      if (k > 0)
        check_argument(e[k] > e[k - 1], "steps_terrain: ", what,
                       " must be strictly increasing, but ", what, "[", k, "] = ", e[k],
                       " <= ", what, "[", k - 1, "] = ", e[k - 1]);
    }
  }

  void validate() const {
    check_argument(std::isfinite(base_), "steps_terrain: base_height must be finite, got ", base_);
    check_argument(xe_.size() >= 2, "steps_terrain: x_edges needs at least 2 values, got ",
                   xe_.size());
    check_argument(ye_.size() >= 2, "steps_terrain: y_edges needs at least 2 values, got ",
                   ye_.size());
    validate_edges(xe_, "x_edges");
    validate_edges(ye_, "y_edges");
    check_size(h_.rows(), static_cast<std::ptrdiff_t>(xe_.size()) - 1,
               "steps_terrain: heights rows (x_edges.size() - 1)");
    check_size(h_.cols(), static_cast<std::ptrdiff_t>(ye_.size()) - 1,
               "steps_terrain: heights cols (y_edges.size() - 1)");
    for (Eigen::Index j = 0; j < h_.cols(); ++j)
      for (Eigen::Index i = 0; i < h_.rows(); ++i)
        check_argument(std::isfinite(h_(i, j)), "steps_terrain: height of cell (", i, ", ", j,
                       ") is not finite (", h_(i, j), ")");
  }

  std::vector<double> xe_, ye_;
  Eigen::MatrixXd h_;
  double base_;
  double max_height_ = 0.0;  ///< the highest tread or the base, m
};

static_assert(terrain_with_penetration<steps_terrain>);

/// Options of random_boxes(); the defaults follow Wu & Popovic 2010 (box heights uniform in
/// [0, 0.2] m) with 1 m boxes over x in [-5, 45] m, y in [-5, 5] m on a ground at 0.
struct random_boxes_options {
  Eigen::Vector2d origin{-5.0, -5.0};  ///< corner of box (0, 0), m
  Eigen::Vector2d size{1.0, 1.0};      ///< box footprint, m
  int nx = 50;                         ///< boxes along x
  int ny = 10;                         ///< boxes along y (1 and a wide size.y for planar models)
  double min_height = 0.0;             ///< m
  double max_height = 0.2;             ///< m
  double base_height = 0.0;            ///< ground outside the boxes, m
};

/// A grid of boxes with independent heights uniform in [min_height, max_height]; equal seeds give
/// identical terrains on every platform.
inline steps_terrain random_boxes(const random_boxes_options& o, std::uint64_t seed) {
  check_argument(o.nx >= 1 && o.ny >= 1, "random_boxes: grid must have nx >= 1 and ny >= 1, got ",
                 o.nx, " x ", o.ny);
  check_argument(
      std::isfinite(o.min_height) && std::isfinite(o.max_height) && o.min_height <= o.max_height,
      "random_boxes: need finite min_height <= max_height, got [", o.min_height, ", ", o.max_height,
      "]");
  std::mt19937_64 rng(seed);
  Eigen::MatrixXd h(o.nx, o.ny);
  for (int j = 0; j < o.ny; ++j)
    for (int i = 0; i < o.nx; ++i)
      h(i, j) = o.min_height + (o.max_height - o.min_height) * detail::uniform01(rng);
  return steps_terrain::boxes(o.origin, o.size, std::move(h), o.base_height);
}

}  // namespace gaitsynth
