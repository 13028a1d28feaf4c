#pragma once
/// \file height_field_terrain.hpp
/// A height field: heights on a regular grid, bilinearly interpolated (Wu & Popovic 2010 optimize
/// on random height fields with 1 m x 1 m spacing and node heights uniform in [0, 0.2] m, a new
/// field per CMA iteration; random_height_field() makes such fields from a seed).
///
/// Node (i, j), 0 <= i < nx, 0 <= j < ny, sits at (origin.x + i * spacing.x, origin.y + j *
/// spacing.y) with height heights(i, j). Inside cell (i, j) with local coordinates
/// u = (x - x_i) / spacing.x, v = (y - y_j) / spacing.y in [0, 1]:
///
///   h = (1-u)(1-v) h00 + u (1-v) h10 + (1-u) v h01 + u v h11
///   dh/dx = ((1-v)(h10 - h00) + v (h11 - h01)) / spacing.x
///   dh/dy = ((1-u)(h01 - h00) + u (h11 - h10)) / spacing.y
///   n = (-dh/dx, -dh/dy, 1) / |(-dh/dx, -dh/dy, 1)|
///
/// Outside the grid the query point is clamped to it, so the field continues as the (constant)
/// edge profile and the gradient across the edge is zero (no exception: queries are on the step
/// loop's hot path; the inputs are checked once, in the constructor). A NaN coordinate reads as the
/// first node along its axis, +-inf as the edge. A grid with a single node along an axis
/// is constant along that axis (nx x 1 is a 2D profile for planar models, which query y = 0).
/// Points on a cell boundary use the cell above them (the last node row uses the last cell); the
/// gradient is discontinuous there, as it is for any bilinear surface.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/detail/uniform01.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

class height_field_terrain {
 public:
  /// \param origin   horizontal position of node (0, 0), m
  /// \param spacing  node spacing along x and y, m (finite, > 0)
  /// \param heights  nx x ny node heights, m (finite, nx >= 1, ny >= 1); heights(i, j) at node (i,
  /// j)
  height_field_terrain(const Eigen::Vector2d& origin, const Eigen::Vector2d& spacing,
                       Eigen::MatrixXd heights)
      : origin_(origin), spacing_(spacing), h_(std::move(heights)) {
    validate();
    max_height_ = h_.maxCoeff();
  }
  /// Same grid spacing along x and y.
  height_field_terrain(const Eigen::Vector2d& origin, double spacing, Eigen::MatrixXd heights)
      : height_field_terrain(origin, Eigen::Vector2d(spacing, spacing), std::move(heights)) {}
  /// Heights from a flat list with x varying fastest: values[i + nx * j] is node (i, j).
  height_field_terrain(const Eigen::Vector2d& origin, const Eigen::Vector2d& spacing, int nx,
                       int ny, const std::vector<double>& values)
      : origin_(origin), spacing_(spacing) {
    check_argument(nx >= 1 && ny >= 1,
                   "height_field_terrain: grid must have nx >= 1 and ny >= 1, got ", nx, " x ", ny);
    check_size(static_cast<std::ptrdiff_t>(values.size()), static_cast<std::ptrdiff_t>(nx) * ny,
               "height_field_terrain: values (nx * ny)");
    h_ = Eigen::Map<const Eigen::MatrixXd>(values.data(), nx, ny);
    validate();
    max_height_ = h_.maxCoeff();
  }

  double height(double x, double y) const {
    const cell c = locate(x, y);
    return (1 - c.u) * (1 - c.v) * c.h00 + c.u * (1 - c.v) * c.h10 + (1 - c.u) * c.v * c.h01 +
           c.u * c.v * c.h11;
  }

  vec3 normal(double x, double y) const {
    const Eigen::Vector2d g = gradient(x, y);
    return vec3(-g.x(), -g.y(), 1.0).normalized();
  }

  /// (dh/dx, dh/dy) of the interpolant; zero across the grid's edge outside the grid.
  Eigen::Vector2d gradient(double x, double y) const {
    const cell c = locate(x, y);
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    if (c.inside_x) g.x() = ((1 - c.v) * (c.h10 - c.h00) + c.v * (c.h11 - c.h01)) / spacing_.x();
    if (c.inside_y) g.y() = ((1 - c.u) * (c.h01 - c.h00) + c.u * (c.h11 - c.h10)) / spacing_.y();
    return g;
  }

  /// The height bound over any disc: the highest node (the bilinear interpolant, and its
  /// extension past the grid's edge, never exceed it).
  double max_height(double /*x*/, double /*y*/, double /*r*/) const { return max_height_; }

  int nx() const { return static_cast<int>(h_.rows()); }
  int ny() const { return static_cast<int>(h_.cols()); }
  const Eigen::Vector2d& origin() const { return origin_; }
  const Eigen::Vector2d& spacing() const { return spacing_; }
  const Eigen::MatrixXd& heights() const { return h_; }
  /// Horizontal position of node (i, j).
  Eigen::Vector2d node(int i, int j) const {
    return origin_ + Eigen::Vector2d(i * spacing_.x(), j * spacing_.y());
  }

 private:
  struct cell {
    double u, v;                // local coordinates in [0, 1]
    double h00, h10, h01, h11;  // corner heights
    bool inside_x, inside_y;    // query strictly inside the grid's extent along that axis
  };

  void validate() const {
    check_argument(origin_.allFinite(), "height_field_terrain: origin must be finite, got (",
                   origin_.transpose(), ")");
    check_positive(spacing_.x(), "height_field_terrain: spacing.x");
    check_positive(spacing_.y(), "height_field_terrain: spacing.y");
    check_argument(h_.rows() >= 1 && h_.cols() >= 1, "height_field_terrain: grid is empty (",
                   h_.rows(), " x ", h_.cols(), " nodes)");
    for (Eigen::Index j = 0; j < h_.cols(); ++j)
      for (Eigen::Index i = 0; i < h_.rows(); ++i)
        check_argument(std::isfinite(h_(i, j)), "height_field_terrain: height of node (", i, ", ",
                       j, ") is not finite (", h_(i, j), ")");
  }

  /// Cell index and local coordinate along one axis, clamped to the grid.
  static void axis(double s, int n, int& i0, int& i1, double& u, bool& inside) {
    inside = false;
    if (n == 1 || !(s >= 0.0)) {  // also catches NaN: treated as the first node
      i0 = i1 = 0;
      u = 0.0;
      return;
    }
    if (s >= n - 1) {
      i0 = i1 = n - 1;
      u = 0.0;
      return;
    }
    inside = true;
    i0 = std::min(static_cast<int>(s), n - 2);
    i1 = i0 + 1;
    u = s - i0;
  }

  cell locate(double x, double y) const {
    int i0, i1, j0, j1;
    cell c;
    axis((x - origin_.x()) / spacing_.x(), nx(), i0, i1, c.u, c.inside_x);
    axis((y - origin_.y()) / spacing_.y(), ny(), j0, j1, c.v, c.inside_y);
    c.h00 = h_(i0, j0);
    c.h10 = h_(i1, j0);
    c.h01 = h_(i0, j1);
    c.h11 = h_(i1, j1);
    return c;
  }

  Eigen::Vector2d origin_;
  Eigen::Vector2d spacing_;
  Eigen::MatrixXd h_;
  double max_height_ = 0.0;  ///< the highest node, m
};

static_assert(terrain<height_field_terrain>);

/// Options of random_height_field(); the defaults are Wu & Popovic 2010's training terrain
/// (1 m x 1 m grid, node heights uniform in [0, 0.2] m) over x in [-5, 45] m, y in [-5, 5] m.
struct random_height_field_options {
  Eigen::Vector2d origin{-5.0, -5.0};  ///< node (0, 0), m
  double spacing = 1.0;                ///< m, both axes
  int nx = 51;                         ///< nodes along x
  int ny = 11;                         ///< nodes along y (1 for a planar profile)
  double min_height = 0.0;             ///< m
  double max_height = 0.2;             ///< m
};

/// A height field whose node heights are independent and uniform in [min_height, max_height]
/// (equal seeds give identical fields on every platform; see detail::uniform01).
inline height_field_terrain random_height_field(const random_height_field_options& o,
                                                std::uint64_t seed) {
  check_argument(o.nx >= 1 && o.ny >= 1,
                 "random_height_field: grid must have nx >= 1 and ny >= 1, got ", o.nx, " x ",
                 o.ny);
  check_argument(
      std::isfinite(o.min_height) && std::isfinite(o.max_height) && o.min_height <= o.max_height,
      "random_height_field: need finite min_height <= max_height, got [", o.min_height, ", ",
      o.max_height, "]");
  std::mt19937_64 rng(seed);
  Eigen::MatrixXd h(o.nx, o.ny);
  for (int j = 0; j < o.ny; ++j)
    for (int i = 0; i < o.nx; ++i)
      h(i, j) = o.min_height + (o.max_height - o.min_height) * detail::uniform01(rng);
  return height_field_terrain(o.origin, o.spacing, std::move(h));
}

}  // namespace gaitsynth
