#pragma once
/// \file keyframes.hpp
/// Cyclic keyframe target motion (Sharon & van de Panne 2005, section II): a few poses with
/// transition times, linearly interpolated, repeated forever. A symmetric walk lists only one step
/// (half a cycle); the next step is the left/right mirror image of the listed one, shifted forward
/// by the stride (`advance`). The target motion guides the optimization (mass-distance cost, eqs.
/// 2-3) and initializes the nearest-neighbor controller's nodes; it is not a reference trajectory
/// that has to be physically realizable.
///
/// Time line of a motion with listed keyframes k_0..k_{n-1} at times 0 = t_0 < ... < t_{n-1} and
/// `end_time` T > t_{n-1}:
///
///     segment s covers [s T, (s + 1) T); within it the pose goes k_0 -> k_1 -> ... -> k_{n-1} ->
///     k_0'
///
/// where k_0' is the first keyframe of segment s + 1: mirrored when the motion is symmetric and
/// shifted by `advance`. Segment s is mirrored when the motion is symmetric and s is odd, and every
/// pose of segment s is shifted by s * advance. The full gait cycle therefore lasts 2T (symmetric)
/// or T (not symmetric) and moves the character by 2 advance or advance.
///
/// Poses are full configurations q (model.nq()): root coordinates first, then joint angles. Root
/// orientations of a floating root are quaternions; they are interpolated by normalized linear
/// interpolation (the same as slerp to first order for the small angles between keyframes).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/motion/stance_side.hpp"

namespace gaitsynth {

/// One keyframe: a full configuration at a time within the listed segment.
struct keyframe {
  double time = 0.0;  ///< s, from the start of the segment (the first keyframe is at 0)
  Eigen::VectorXd q;  ///< model.nq(): root coordinates, then joint angles (rad)
};

// stance_side (motion/stance_side.hpp): which leg supports the body during the listed segment (the
// mirrored segment uses the other).

/// Mirrors a configuration across the sagittal (x-z) plane: left and right joint DOFs swap (with
/// the model's mirror signs); a planar root is unchanged, a floating root maps (x, y, z) to
/// (x, -y, z) and its quaternion (w, x, y, z) to (w, -x, y, -z). Writes into `out` (may alias `q`
/// only if the model has no left/right pairs; use a separate vector otherwise).
template <root_joint Root>
void mirror_configuration(const model<Root>& m, const Eigen::Ref<const Eigen::VectorXd>& q,
                          Eigen::Ref<Eigen::VectorXd> out) {
  constexpr int nr = Root::nq;
  if constexpr (nr == 7) {
    out[0] = q[0];
    out[1] = -q[1];
    out[2] = q[2];
    out[3] = q[3];
    out[4] = -q[4];
    out[5] = q[5];
    out[6] = -q[6];
  } else {
    for (int i = 0; i < nr; ++i) out[i] = q[i];
  }
  for (int j = 0; j < m.num_joint_dofs(); ++j)
    out[nr + j] = m.mirror_sign[j] * q[nr + m.mirror_dof[j]];
}

/// A cyclic keyframe target motion. Immutable after construction (shared by threads); pose queries
/// write into caller-provided vectors and never allocate.
template <root_joint Root>
class keyframe_motion {
 public:
  using model_type = model<Root>;

  /// \param m         the character (only its DOF count and mirror map are used; it must outlive
  ///                  nothing: the needed data are copied)
  /// \param frames    listed keyframes, times strictly increasing from 0
  /// \param end_time  time at which the listed segment wraps to its first keyframe (> last time)
  /// \param symmetric true: odd segments are the left/right mirror of the listed one
  /// \param advance   root displacement per segment (size Root::nq, or empty for none); only the
  ///                  translational root coordinates may be non-zero (planar: root_x, root_z)
  /// \param stance    which leg supports the body during the listed segment (informative; the
  ///                  nearest-neighbor controller uses it to pick the torso servo's hip)
  /// Throws std::invalid_argument naming the bad value.
  keyframe_motion(const model_type& m, std::vector<keyframe> frames, double end_time,
                  bool symmetric, Eigen::VectorXd advance = {},
                  stance_side stance = stance_side::none)
      : frames_(std::move(frames)),
        end_time_(end_time),
        symmetric_(symmetric),
        stance_(stance),
        nq_(m.nq()),
        nv_(m.nv()) {
    check_argument(!frames_.empty(), "keyframe_motion: no keyframes");
    for (std::size_t k = 0; k < frames_.size(); ++k) {
      const keyframe& f = frames_[k];
      check_argument(f.q.size() == nq_, "keyframe_motion: keyframe ", k, " has ", f.q.size(),
                     " coordinates, model '", m.name, "' needs nq = ", nq_);
      check_argument(std::isfinite(f.time), "keyframe_motion: keyframe ", k,
                     " time is not finite (", f.time, ")");
      for (int i = 0; i < nq_; ++i)
        check_argument(std::isfinite(f.q[i]), "keyframe_motion: keyframe ", k, " coordinate ", i,
                       " is not finite (", f.q[i], ")");
      if (k == 0)
        check_argument(f.time == 0.0, "keyframe_motion: the first keyframe must be at time 0, got ",
                       f.time);
      else
        check_argument(f.time > frames_[k - 1].time,
                       "keyframe_motion: keyframe times must increase: keyframe ", k, " at ",
                       f.time, " s is not after keyframe ", k - 1, " at ", frames_[k - 1].time,
                       " s");
      if constexpr (Root::nq == 7) {
        const double n = f.q.template segment<4>(3).norm();
        check_argument(n > 1e-9, "keyframe_motion: keyframe ", k, " has a zero root quaternion");
        frames_[k].q.template segment<4>(3) /= n;
      }
    }
    check_argument(std::isfinite(end_time_) && end_time_ > frames_.back().time,
                   "keyframe_motion: end_time must be after the last keyframe (",
                   frames_.back().time, " s), got ", end_time_);
    if (advance.size() == 0) advance = Eigen::VectorXd::Zero(Root::nq);
    check_argument(advance.size() == Root::nq, "keyframe_motion: advance has ", advance.size(),
                   " entries, the root has ", Root::nq);
    check_finite(advance, "keyframe_motion: advance");
    if constexpr (Root::nq == 3) {
      check_argument(advance[2] == 0.0, "keyframe_motion: advance of root_pitch must be 0, got ",
                     advance[2]);
    } else if constexpr (Root::nq == 7) {
      check_argument(advance.template tail<4>().isZero(),
                     "keyframe_motion: advance of the root quaternion must be 0");
    }
    advance_ = Eigen::VectorXd::Zero(nq_);
    advance_.head(Root::nq) = advance;
    // Precompute the keyframes of one full cycle: the listed ones, then (symmetric) their mirrors
    // shifted by one advance. The closing keyframe of the cycle is cycle_[0] + cycle advance.
    const int n = num_keyframes();
    cycle_.resize(symmetric_ ? 2 * n : n);
    for (int k = 0; k < n; ++k) cycle_[k] = frames_[k];
    if (symmetric_) {
      for (int k = 0; k < n; ++k) {
        cycle_[n + k].time = end_time_ + frames_[k].time;
        cycle_[n + k].q.resize(nq_);
        mirror_configuration(m, frames_[k].q, cycle_[n + k].q);
        cycle_[n + k].q += advance_;
      }
    }
  }

  int nq() const { return nq_; }
  int nv() const { return nv_; }
  /// Number of listed keyframes.
  int num_keyframes() const { return static_cast<int>(frames_.size()); }
  const std::vector<keyframe>& keyframes() const { return frames_; }
  /// Keyframes of one full cycle (listed, then mirrored ones when symmetric), with cycle times.
  const std::vector<keyframe>& cycle_keyframes() const { return cycle_; }
  double end_time() const { return end_time_; }
  bool symmetric() const { return symmetric_; }
  stance_side stance() const { return stance_; }
  /// Root displacement per segment (size nq, zero outside the root's translation).
  const Eigen::VectorXd& advance() const { return advance_; }
  /// Duration of one full gait cycle: 2 end_time (symmetric) or end_time.
  double period() const { return symmetric_ ? 2.0 * end_time_ : end_time_; }
  /// Root displacement per full cycle.
  Eigen::VectorXd cycle_advance() const { return (symmetric_ ? 2.0 : 1.0) * advance_; }
  /// Average target speed along x, m/s.
  double speed() const { return advance_[0] / end_time_; }

  /// Index of the segment containing t (segment s covers [s T, (s+1) T)).
  long segment(double t) const { return static_cast<long>(std::floor(t / end_time_)); }
  /// True when t lies in a mirrored segment.
  bool mirrored_at(double t) const { return symmetric_ && (segment(t) % 2 != 0); }
  /// The stance leg of the target motion at time t.
  stance_side stance_at(double t) const { return mirrored_at(t) ? opposite(stance_) : stance_; }

  /// Target configuration at time t (any real t; the motion extends periodically backwards too).
  /// `q` must have size nq(). No allocation.
  void pose(double t, Eigen::Ref<Eigen::VectorXd> q) const {
    int k0, k1;
    double a;
    Eigen::Index shift_cycles;
    locate(t, k0, k1, a, shift_cycles);
    const Eigen::VectorXd& q0 = cycle_[k0].q;
    const Eigen::VectorXd& q1 = cycle_[k1].q;
    const double cyc = symmetric_ ? 2.0 : 1.0;
    // The closing keyframe (k1 wrapped to 0) belongs to the next cycle: shift it by one cycle.
    const double extra = (k1 == 0) ? cyc : 0.0;
    q = (1.0 - a) * q0 + a * q1 + (a * extra + static_cast<double>(shift_cycles) * cyc) * advance_;
    if constexpr (Root::nq == 7) q.template segment<4>(3).normalize();
  }

  /// Target generalized velocity at time t (the slope of the interpolation; piecewise constant,
  /// right-continuous). `v` must have size nv(). No allocation.
  void velocity(double t, Eigen::Ref<Eigen::VectorXd> v) const {
    int k0, k1;
    double a;
    Eigen::Index shift_cycles;
    locate(t, k0, k1, a, shift_cycles);
    const double cyc = symmetric_ ? 2.0 : 1.0;
    const double t0 = cycle_[k0].time;
    const double t1 = (k1 == 0) ? cyc * end_time_ : cycle_[k1].time;
    const double dt = t1 - t0;
    const Eigen::VectorXd& q0 = cycle_[k0].q;
    const Eigen::VectorXd& q1 = cycle_[k1].q;
    const double extra = (k1 == 0) ? cyc : 0.0;
    constexpr int nr = Root::nq;
    const int nj = nq_ - nr;
    v.tail(nj) = (q1.tail(nj) - q0.tail(nj)) / dt;
    if constexpr (nr == 7) {
      v.template head<3>() =
          (q1.template head<3>() + extra * advance_.template head<3>() - q0.template head<3>()) /
          dt;
      // Body-frame angular velocity of the nlerp at parameter a: omega = 2 conj(q) dq/dt.
      const Eigen::Vector4d c0 = q0.template segment<4>(3), c1 = q1.template segment<4>(3);
      const Eigen::Vector4d c = (1.0 - a) * c0 + a * c1;
      const double n = c.norm();
      const Eigen::Vector4d dc = (c1 - c0) / dt;
      const Eigen::Vector4d dqn = dc / n - c * (c.dot(dc)) / (n * n * n);
      const Eigen::Quaterniond qq(c[0] / n, c[1] / n, c[2] / n, c[3] / n);
      const Eigen::Quaterniond dq(dqn[0], dqn[1], dqn[2], dqn[3]);
      const Eigen::Quaterniond w = qq.conjugate() * dq;
      v.template segment<3>(3) = 2.0 * Eigen::Vector3d(w.x(), w.y(), w.z());
    } else {
      v.head(nr) = (q1.head(nr) + extra * advance_.head(nr) - q0.head(nr)) / dt;
    }
  }

  /// The initial simulation state of section V.B: the pose at the first keyframe and the velocity
  /// of the first transition (time 0).
  sim_state initial_state() const {
    sim_state s;
    s.q.resize(nq_);
    s.v.resize(nv_);
    pose(0.0, s.q);
    velocity(0.0, s.v);
    s.t = 0.0;
    return s;
  }

 private:
  // Finds the cycle keyframes k0 -> k1 bracketing t, the interpolation parameter a in [0, 1) and
  // the number of whole cycles before t.
  void locate(double t, int& k0, int& k1, double& a, Eigen::Index& shift_cycles) const {
    check_argument(std::isfinite(t), "keyframe_motion: time is not finite (", t, ")");
    const double P = period();
    const double c = std::floor(t / P);
    shift_cycles = static_cast<Eigen::Index>(c);
    double tau = t - c * P;
    if (tau >= P) tau = 0.0, ++shift_cycles;  // rounding
    if (tau < 0.0) tau = 0.0;
    const int n = static_cast<int>(cycle_.size());
    // Last keyframe with time <= tau (cycle_ is short: a linear scan is fastest).
    k0 = 0;
    for (int k = 1; k < n; ++k)
      if (cycle_[k].time <= tau) k0 = k;
    k1 = (k0 + 1) % n;
    const double t0 = cycle_[k0].time;
    const double t1 = (k1 == 0) ? P : cycle_[k1].time;
    a = std::clamp((tau - t0) / (t1 - t0), 0.0, 1.0);
  }

  std::vector<keyframe> frames_;
  std::vector<keyframe> cycle_;
  double end_time_;
  bool symmetric_;
  stance_side stance_;
  Eigen::VectorXd advance_;
  int nq_, nv_;
};

}  // namespace gaitsynth
