// World-frame angles of Wang et al. 2009 Sec. 3 (spatial/world_angles.hpp): analytic rotations
// about one axis read back exactly, the heading frame removes a yaw, and the signs match the
// joints' (a forward-swung thigh is negative, toes-down is positive).
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "gaitsynth/spatial/world_angles.hpp"

using namespace gaitsynth;

namespace {
mat3 rot(int axis, double a) {
  return Eigen::AngleAxisd(a, vec3::Unit(axis)).toRotationMatrix();
}
}  // namespace

TEST_CASE("world angles: a rotation about one axis reads back as that axis's angle", "[spatial]") {
  for (const double a : {-1.2, -0.3, 0.0, 0.05, 0.7, 1.4}) {
    for (int axis = 0; axis < 3; ++axis) {
      const world_angles w = body_world_angles(rot(axis, a));
      for (int k = 0; k < 3; ++k) CHECK(w[k] == Approx(k == axis ? a : 0.0).margin(1e-15));
    }
  }
  // Transverse angles past pi/2 (a body facing backwards) read back too.
  CHECK(body_world_angles(rot(2, 2.5)).transverse == Approx(2.5).margin(1e-15));
  CHECK(body_world_angles(rot(2, 2.5)).norm() == Approx(2.5));
}

TEST_CASE("world angles: the heading frame removes the heading's yaw", "[spatial]") {
  const double heading = 0.9;
  const mat3 R = rot(2, heading) * rot(1, 0.4) * rot(0, -0.2);
  const world_angles w = body_world_angles(R, heading);
  const world_angles w0 = body_world_angles(rot(1, 0.4) * rot(0, -0.2));
  CHECK(w.coronal == Approx(w0.coronal).margin(1e-14));
  CHECK(w.sagittal == Approx(w0.sagittal).margin(1e-14));
  CHECK(w.transverse == Approx(w0.transverse).margin(1e-14));
  CHECK(body_heading(R) == Approx(heading).margin(1e-14));
  // The up vector's projections: sagittal tan = u_x / u_z, coronal tan = -u_y / u_z.
  const vec3 up = to_heading_frame(R.col(2), heading);
  CHECK(std::tan(w.sagittal) == Approx(up.x() / up.z()));
  CHECK(std::tan(w.coronal) == Approx(-up.y() / up.z()));
}

TEST_CASE("world angles: signs agree with the humanoid's joint conventions", "[spatial]") {
  // A thigh hangs along -z of its body frame; swinging it forward (hip flexion, negative hip_y)
  // moves its distal end to +x and gives a negative sagittal angle.
  const mat3 thigh = rot(1, -0.5);
  CHECK((thigh * vec3(0, 0, -1)).x() > 0.0);
  CHECK(body_world_angles(thigh).sagittal == Approx(-0.5));
  // A foot pointing along +x with its toes down (plantarflexion, positive ankle_y) is positive.
  const mat3 foot = rot(1, 0.3);
  CHECK((foot * vec3(1, 0, 0)).z() < 0.0);
  CHECK(body_world_angles(foot).sagittal == Approx(0.3));
}

TEST_CASE("world angles: the tilt from the vertical ignores heading and lean direction",
          "[spatial]") {
  for (const double heading : {0.0, 1.0, -2.5})
    for (const double lean : {0.0, 0.3, 1.2, 2.9})
      for (const double dir : {0.0, 0.7, 2.0, -1.5}) {
        // Lean about a horizontal axis at angle dir, after any heading.
        const Eigen::Vector3d axis(std::cos(dir), std::sin(dir), 0.0);
        const Eigen::Matrix3d R =
            (Eigen::AngleAxisd(lean, axis) * Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()))
                .toRotationMatrix();
        CHECK(gaitsynth::tilt_from_vertical(R.col(2)) == Approx(lean).margin(1e-12));
      }
  CHECK(gaitsynth::tilt_from_vertical(-Eigen::Vector3d::UnitZ()) == Approx(std::numbers::pi));
}

TEST_CASE("world_angles_norm_exceeds answers as the definition does, near the limit too",
          "[spatial]") {
  // Random rotations at every scale (well inside, near and far beyond 0.1 rad, facing backwards
  // and upside down) and rotations whose norm is the limit to the last bits: the bounds must
  // never decide a case the definition decides the other way.
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // splitmix64, so the case list is the same on every platform
    state += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  for (const double scale : {0.01, 0.05, 0.08, 0.1, 0.12, 0.3, 1.0, 3.0}) {
    for (int k = 0; k < 400; ++k) {
      const mat3 R = rot(2, scale * (2.0 * uniform() - 1.0)) *
                     rot(1, scale * (2.0 * uniform() - 1.0)) *
                     rot(0, scale * (2.0 * uniform() - 1.0));
      for (const double limit : {0.1, 0.0, 0.5}) {
        INFO("scale " << scale << ", case " << k << ", limit " << limit);
        CHECK(world_angles_norm_exceeds(R, limit) == (body_world_angles(R).norm() > limit));
      }
    }
  }
  // On the limit: the norm of a rotation about one axis by exactly the limit, and one ulp apart.
  for (int axis = 0; axis < 3; ++axis) {
    const mat3 R = rot(axis, 0.1);
    const double norm = body_world_angles(R).norm();
    for (const double limit : {norm, std::nextafter(norm, 0.0), std::nextafter(norm, 1.0), 0.1})
      CHECK(world_angles_norm_exceeds(R, limit) == (norm > limit));
  }
}
