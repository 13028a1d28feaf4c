#pragma once
/// \file dynamics_support.hpp
/// Shared test helpers of the dynamics module: random kinematic trees (any root, branching,
/// multi-DOF bodies, random axes, offsets and inertias), random states, and an approximate-equality
/// matcher for Eigen objects with absolute + relative tolerance.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>
#include <sstream>
#include <string>

#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model_builder.hpp"

namespace gaitsynth::testing {

struct random_model_options {
  int num_bodies = 8;          ///< including the root body
  int max_dofs_per_body = 3;   ///< each non-root body gets 1..max DOFs
  bool random_axes = true;     ///< false: axes drawn from the coordinate axes
  bool branching = true;       ///< false: a serial chain
  double offset_scale = 0.3;   ///< m, joint offsets uniform in [-scale, scale]^3
  bool with_contacts = true;   ///< one contact point per body
};

/// A random principal-moment triple satisfying the triangle inequality, rotated randomly.
inline Eigen::Matrix3d random_inertia(std::mt19937& rng, double scale = 0.1) {
  std::uniform_real_distribution<double> u(0.2, 1.0), f(0.15, 0.85);
  const double a = scale * u(rng), b = scale * u(rng);
  const double lo = std::abs(a - b), hi = a + b;
  const double c = lo + (hi - lo) * f(rng);
  std::normal_distribution<double> g;
  const Eigen::Vector4d qv(g(rng), g(rng), g(rng), g(rng));
  const Eigen::Quaterniond r(qv.normalized());
  const Eigen::Matrix3d R = r.toRotationMatrix();
  Eigen::Matrix3d I = R * Eigen::Vector3d(a, b, c).asDiagonal() * R.transpose();
  return 0.5 * (I + I.transpose());
}

inline Eigen::Vector3d random_vec3(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

inline Eigen::Vector3d random_axis(std::mt19937& rng, bool random_axes) {
  if (!random_axes) {
    std::uniform_int_distribution<int> k(0, 2);
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    a[k(rng)] = std::bernoulli_distribution(0.5)(rng) ? 1.0 : -1.0;
    return a;
  }
  std::normal_distribution<double> g;
  Eigen::Vector3d a(g(rng), g(rng), g(rng));
  return a.normalized();
}

/// A random valid model (builds through model_builder, so it is validated like user models).
template <root_joint Root>
model<Root> random_model(std::mt19937& rng, const random_model_options& o = {}) {
  model_builder<Root> b(detail::concat("random_", Root::name));
  std::uniform_real_distribution<double> mass(0.5, 5.0);
  b.add_body({.name = "b0", .mass = mass(rng), .com = random_vec3(rng, 0.1),
              .inertia = random_inertia(rng)});
  for (int i = 1; i < o.num_bodies; ++i) {
    int parent = i - 1;
    if (o.branching) parent = std::uniform_int_distribution<int>(0, i - 1)(rng);
    const int nd = std::uniform_int_distribution<int>(1, o.max_dofs_per_body)(rng);
    // The axes of one body must be well independent (two parallel hinges in one body would make
    // M(q) singular): distinct coordinate axes, or random axes far from each other's span.
    std::vector<Eigen::Vector3d> axes;
    while (static_cast<int>(axes.size()) < nd) {
      const Eigen::Vector3d a = random_axis(rng, o.random_axes);
      bool ok = true;
      for (const auto& b2 : axes) ok = ok && std::abs(a.dot(b2)) < 0.8;
      if (axes.size() == 2) ok = ok && std::abs(a.dot(axes[0].cross(axes[1]).normalized())) > 0.4;
      if (ok) axes.push_back(a);
    }
    std::vector<dof_spec> dofs;
    for (int k = 0; k < nd; ++k)
      dofs.push_back({.name = detail::concat("j", i, "_", k), .axis = axes[k]});
    b.add_body({.name = detail::concat("b", i), .parent = detail::concat("b", parent),
                .joint_offset = random_vec3(rng, o.offset_scale), .mass = mass(rng),
                .com = random_vec3(rng, 0.15), .inertia = random_inertia(rng),
                .dofs = std::move(dofs)});
  }
  if (o.with_contacts)
    for (int i = 0; i < o.num_bodies; ++i)
      b.add_contact_point({.name = detail::concat("c", i), .body = detail::concat("b", i),
                           .position = random_vec3(rng, 0.1)});
  return b.build();
}

inline Eigen::VectorXd random_vector(std::mt19937& rng, int n, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = u(rng);
  return x;
}

/// Matches an Eigen object within |a - b| <= atol + rtol * max(|b|_max, 1) elementwise.
class approx_matcher : public Catch::MatcherBase<Eigen::MatrixXd> {
 public:
  approx_matcher(Eigen::MatrixXd expected, double rtol, double atol)
      : expected_(std::move(expected)), rtol_(rtol), atol_(atol) {}
  bool match(const Eigen::MatrixXd& actual) const override {
    if (actual.rows() != expected_.rows() || actual.cols() != expected_.cols()) return false;
    if (!actual.allFinite()) return false;
    if (actual.size() == 0) return true;
    const double scale = std::max(1.0, expected_.cwiseAbs().maxCoeff());
    return (actual - expected_).cwiseAbs().maxCoeff() <= atol_ + rtol_ * scale;
  }
  std::string describe() const override {
    std::ostringstream os;
    os.precision(12);
    os << "is approximately (rtol " << rtol_ << ", atol " << atol_ << ")\n" << expected_;
    return os.str();
  }

 private:
  Eigen::MatrixXd expected_;
  double rtol_, atol_;
};

template <class Derived>
approx_matcher is_approx(const Eigen::MatrixBase<Derived>& expected, double rtol = 1e-9,
                         double atol = 0.0) {
  return approx_matcher(Eigen::MatrixXd(expected), rtol, atol);
}

}  // namespace gaitsynth::testing

namespace Catch {
template <>
struct StringMaker<Eigen::MatrixXd> {
  static std::string convert(const Eigen::MatrixXd& m) {
    std::ostringstream os;
    os.precision(12);
    os << "\n" << m;
    return os.str();
  }
};
}  // namespace Catch
