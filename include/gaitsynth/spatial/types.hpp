#pragma once
/// \file types.hpp
/// Fixed-size Eigen aliases shared by every module.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace gaitsynth {
using vec3 = Eigen::Vector3d;
using mat3 = Eigen::Matrix3d;
using vec6 = Eigen::Matrix<double, 6, 1>;
using mat6 = Eigen::Matrix<double, 6, 6>;
using quat = Eigen::Quaterniond;
}  // namespace gaitsynth
