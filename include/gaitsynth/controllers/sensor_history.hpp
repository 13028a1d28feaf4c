#pragma once
/// \file sensor_history.hpp
/// Ring buffer of the last `capacity` physics-step samples of what a controller may read with a
/// neural delay (Wang et al. 2012 Sec. 4: 5 ms at the hip, 10 ms for VAS and ground contact,
/// 20 ms at the ankle): q, v, contact counts per body, the COM and its velocity, every body's
/// world rotation (balance laws on delayed trunk orientation), and the actuator's sensed values
/// (normalized muscle force and fiber length: actuators/concept.hpp, `sense`). Sized once
/// (reset), then push() never allocates. The rollout pushes one sample per physics step, after
/// contact and before the controller, only when the controller declares a max_sensor_delay.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <span>

#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// One sample as the rollout hands it to sensor_history::push (non-owning).
struct sensor_sample {
  const Eigen::VectorXd* q = nullptr;
  const Eigen::VectorXd* v = nullptr;
  std::span<const int> contact_count;  ///< per body
  vec3 com = vec3::Zero();
  vec3 com_velocity = vec3::Zero();
  std::span<const mat3> body_rotation;  ///< per body
  std::span<const double> sensed;       ///< the actuator's sensed values (may be empty)
};

class sensor_history {
 public:
  /// Sizes the buffer (allocates; set-up only). capacity 0 disables the history.
  void reset(int nq, int nv, int num_bodies, int capacity, int num_sensed = 0) {
    capacity_ = std::max(capacity, 0);
    q_.resize(nq, capacity_);
    v_.resize(nv, capacity_);
    counts_.resize(num_bodies, capacity_);
    com_.resize(6, capacity_);
    rotation_.resize(9 * num_bodies, capacity_);
    sensed_.resize(std::max(num_sensed, 0), capacity_);
    head_ = -1;
    size_ = 0;
  }
  int capacity() const { return capacity_; }
  int size() const { return size_; }
  int num_sensed() const { return static_cast<int>(sensed_.rows()); }

  /// Appends the newest sample (overwrites the oldest when full). No allocation.
  void push(const sensor_sample& x) {
    if (capacity_ == 0) return;
    head_ = (head_ + 1) % capacity_;
    q_.col(head_) = *x.q;
    v_.col(head_) = *x.v;
    for (int b = 0; b < counts_.rows(); ++b) counts_(b, head_) = x.contact_count[b];
    com_.col(head_).head<3>() = x.com;
    com_.col(head_).tail<3>() = x.com_velocity;
    for (int b = 0; b < counts_.rows(); ++b)
      rotation_.col(head_).segment<9>(9 * b) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(
          x.body_rotation[static_cast<std::size_t>(b)].data());
    for (Eigen::Index i = 0; i < sensed_.rows(); ++i)
      sensed_(i, head_) = x.sensed[static_cast<std::size_t>(i)];
    size_ = std::min(size_ + 1, capacity_);
  }

  /// Column index of the sample `back` steps before the newest, clamped to the oldest stored one.
  int index(int back) const {
    back = std::clamp(back, 0, std::max(size_ - 1, 0));
    return ((head_ - back) % capacity_ + capacity_) % capacity_;
  }
  auto q(int back) const { return q_.col(index(back)); }
  auto v(int back) const { return v_.col(index(back)); }
  int contact_count(int back, int body) const { return counts_(body, index(back)); }
  vec3 com(int back) const { return com_.col(index(back)).head<3>(); }
  vec3 com_velocity(int back) const { return com_.col(index(back)).tail<3>(); }
  mat3 body_rotation(int back, int body) const {
    return Eigen::Map<const mat3>(rotation_.col(index(back)).segment<9>(9 * body).data());
  }
  auto sensed(int back) const { return sensed_.col(index(back)); }

 private:
  Eigen::MatrixXd q_, v_, com_, rotation_, sensed_;
  Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic> counts_;
  int capacity_ = 0, head_ = -1, size_ = 0;
};

/// Number of history samples a delay needs at timestep dt (delay 0 needs 1: the current sample).
inline int history_capacity(double max_delay, double dt) {
  if (!(max_delay > 0.0) || !(dt > 0.0)) return 0;
  return static_cast<int>(std::ceil(max_delay / dt - 1e-9)) + 1;
}

}  // namespace gaitsynth
