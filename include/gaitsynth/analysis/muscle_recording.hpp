#pragma once
/// \file analysis/muscle_recording.hpp
/// Each MTU's excitation, activation, normalized force and normalized fiber length over a rollout
/// of a musculotendon_actuator, for curves over the gait cycle (Wang et al. 2012, Figure 5: GAS
/// activation and normalized fiber length in stance; issue 13):
///
///   muscle_recording mr;
///   trajectory tr;
///   opt.record = &tr;
///   opt.record_every = 40;
///   rollout(m, act, ctrl, obj, ground, integ, params, opt, scratch,
///           musculotendon_recorder(act, &mr, 40));
///   gait_cycle_options o;
///   o.channels = muscle_gait_channels(mr, "lGAS");
///   const gait_cycle_data d = gait_cycles(m, tr, o);
///
/// The recorder samples the steps the trajectory_observer of the same `every` records (steps
/// 0, every, 2 every, ... and the state the rollout stopped in), so the two line up frame by
/// frame; gait_channel::kind::recorded interpolates by time, so other spacings work too.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/observer.hpp"
#include "gaitsynth/rollout/result.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"

namespace gaitsynth {

/// What musculotendon_recorder writes: per MTU (the actuator's order) one value per sample.
struct muscle_recording {
  std::vector<std::string> names;  ///< MTU names ("lGAS")
  std::vector<double> time;        ///< s, per sample
  /// u of the physics step before the sample (clamped to [0, 1]; the actuator's initial
  /// activation at the first sample): the excitation that drove the activation to its value.
  std::vector<std::vector<double>> excitation;               ///< [mtu][sample]
  std::vector<std::vector<double>> activation;               ///< [mtu][sample], a in [0, 1]
  std::vector<std::vector<double>> normalized_force;         ///< [mtu][sample], F_MTU / F_max
  std::vector<std::vector<double>> normalized_fiber_length;  ///< [mtu][sample], l_CE / l_opt

  int num_samples() const { return static_cast<int>(time.size()); }
  /// Index of MTU `name`, -1 if there is none.
  int index_of(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return static_cast<int>(i);
    return -1;
  }
};

/// A rollout observer (rollout/observer.hpp) that records the muscle state of a
/// musculotendon_actuator every `every` physics steps, plus the state the rollout stopped in, as
/// rollout/recorder.hpp's trajectory_observer does. All memory is reserved in start(); observe()
/// only writes into it. A null recording records nothing.
class musculotendon_recorder {
 public:
  /// act: the rollout's actuator (its MTU names and F_max, l_opt are copied here).
  musculotendon_recorder(const musculotendon_actuator& act, muscle_recording* rec, int every = 1)
      : rec_(rec), every_(every) {
    check_argument(every >= 1, "musculotendon_recorder: every must be >= 1, got ", every);
    for (const auto& u : act.units()) {
      names_.push_back(u.name);
      max_force_.push_back(u.parameters.max_isometric_force);
      optimal_length_.push_back(u.parameters.optimal_fiber_length);
    }
  }

  /// Prepares the recording for at most horizon_steps / every + 1 samples.
  template <root_joint Root>
  void start(const model<Root>&, const observer_setup& su) {
    count_ = 0;
    last_ = -1;
    if (rec_ == nullptr) return;
    const std::int64_t samples = su.horizon_steps / every_ + 1;
    const std::vector<double> zeros(static_cast<std::size_t>(std::max<std::int64_t>(samples, 0)),
                                    0.0);
    rec_->names = names_;
    rec_->time = zeros;
    for (auto* series : {&rec_->excitation, &rec_->activation, &rec_->normalized_force,
                         &rec_->normalized_fiber_length})
      series->assign(names_.size(), zeros);
  }

  template <class Observation>
  void observe(const Observation& ob) {
    if (rec_ != nullptr && ob.step % every_ == 0 && count_ < rec_->time.size()) fill(ob);
  }

  /// The state it stopped in (unless already recorded), then trims the unused samples.
  template <class Observation>
  void finish(const Observation& ob, const rollout_result&) {
    if (rec_ == nullptr) return;
    if (ob.final_state_valid && count_ < rec_->time.size() && last_ != ob.step) fill(ob);
    rec_->time.resize(count_);
    for (auto* series : {&rec_->excitation, &rec_->activation, &rec_->normalized_force,
                         &rec_->normalized_fiber_length})
      for (auto& s : *series) s.resize(count_);
  }

 private:
  template <class Observation>
  void fill(const Observation& ob) {
    const auto& st = ob.actuator_state();
    static_assert(std::is_same_v<std::remove_cvref_t<decltype(st)>, musculotendon_state>,
                  "musculotendon_recorder observes rollouts of a musculotendon_actuator");
    check_argument(static_cast<std::size_t>(st.activation.size()) == names_.size(),
                   "musculotendon_recorder: the rollout's actuator has ", st.activation.size(),
                   " MTUs, the recorder's ", names_.size());
    last_ = ob.step;
    const std::size_t k = count_++;
    rec_->time[k] = ob.t;
    for (std::size_t i = 0; i < names_.size(); ++i) {
      const auto e = static_cast<Eigen::Index>(i);
      rec_->excitation[i][k] = st.excitation[e];
      rec_->activation[i][k] = st.activation[e];
      rec_->normalized_force[i][k] = st.force[e] / max_force_[i];
      rec_->normalized_fiber_length[i][k] = st.fiber_length[e] / optimal_length_[i];
    }
  }

  muscle_recording* rec_ = nullptr;
  int every_ = 1;
  std::vector<std::string> names_;
  std::vector<double> max_force_;       ///< F_max per MTU, N
  std::vector<double> optimal_length_;  ///< l_opt per MTU, m
  std::size_t count_ = 0;
  std::int64_t last_ = -1;
};

/// Gait-plot channels (gait_channel::kind::recorded) of MTU `mtu` of r: excitation u,
/// activation a, F_MTU / F_max and l_CE / l_opt, labelled "<mtu> excitation" etc. Throws
/// std::invalid_argument naming `mtu` and the recorded MTUs when r has no MTU of that name.
inline std::vector<gait_channel> muscle_gait_channels(const muscle_recording& r,
                                                      const std::string& mtu) {
  const int i = r.index_of(mtu);
  if (i < 0) {
    std::string known;
    for (const auto& n : r.names) known += (known.empty() ? "" : ", ") + n;
    check_argument(false, "muscle_gait_channels: no MTU '", mtu,
                   "' in the recording; it has: ", known.empty() ? std::string("none") : known);
  }
  const auto k = static_cast<std::size_t>(i);
  auto channel = [&](const char* what, const std::vector<std::vector<double>>& series,
                     const char* unit) {
    check_argument(series.size() == r.names.size(), "muscle_gait_channels: the recording's ", what,
                   " has ", series.size(), " MTUs, its names ", r.names.size());
    gait_channel c;
    c.type = gait_channel::kind::recorded;
    c.label = mtu + " " + what;
    c.name = mtu;
    c.scale = 1.0;
    c.unit = unit;
    c.series_time = r.time;
    c.series_value = series[k];
    return c;
  };
  return {channel("excitation", r.excitation, ""), channel("activation", r.activation, ""),
          channel("force", r.normalized_force, "F_max"),
          channel("fiber length", r.normalized_fiber_length, "l_opt")};
}

/// Each MTU's activation averaged over the samples at or after t_from (s), in r's MTU order: how
/// hard a gait leans on each muscle (Wang et al. 2012, Sec. 6.2: min_torque keeps TA "highly
/// activated throughout the gait"; min_act lowers GAS/SOL and raises VAS). A plain mean of the
/// samples: the recorder spaces them evenly (only the final one may be closer). Throws
/// std::invalid_argument naming t_from when no sample is that late.
inline std::vector<double> mean_activation(const muscle_recording& r, double t_from) {
  check_argument(r.activation.size() == r.names.size(), "mean_activation: the recording has ",
                 r.activation.size(), " activation series for ", r.names.size(), " MTUs");
  std::vector<double> mean(r.names.size(), 0.0);
  std::size_t n = 0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    if (!(r.time[k] >= t_from)) continue;
    ++n;
    for (std::size_t i = 0; i < mean.size(); ++i) mean[i] += r.activation[i][k];
  }
  check_argument(n > 0, "mean_activation: no sample at or after t_from = ", t_from,
                 " s (the recording ends at ", r.time.empty() ? 0.0 : r.time.back(), " s)");
  for (double& a : mean) a /= static_cast<double>(n);
  return mean;
}

}  // namespace gaitsynth
