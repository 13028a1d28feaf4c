#pragma once
/// \file analysis/human_gait_comparison.hpp
/// A walk's sagittal hip, knee and ankle angles and internal moments per kg over its gait cycles,
/// next to a person's (data/normative_gait/), each with its standard score (standard_score.hpp):
/// Wang et al. 2012 Sec. 6 and Wang et al. 2009 Fig. 6 set their walkers' curves against human
/// data; this puts a number on how far each curve lies.
///
///   const normative_gait human = load_normative_gait(".../falisse2019_subject1_walking.csv");
///   const human_gait_comparison c = compare_with_human(m, tr, human);
///   for (std::size_t k = 0; k < c.labels.size(); ++k) use(c.labels[k], c.scores[k]);
///
/// The channels are human_sagittal_channels then human_sagittal_moment_channels of one side, in
/// the data's conventions and variable names; the moments are the actuator's joint torques (frame
/// tau) over the model's mass, so a walker is compared per kg with a person of another mass.
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "gaitsynth/analysis/standard_score.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/io/normative_gait.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"

namespace gaitsynth {

struct human_comparison_options {
  std::string side = "l";  ///< "l" or "r": whose joints, and whose heel strikes start the cycles
  double t_from = 2.0;     ///< s: frames before it are left out (the start's transient)
  int samples = 100;       ///< per cycle (data/normative_gait/ has 100)
  std::vector<double> cycle_starts;  ///< s; empty: the side's heel strikes (gait_cycles)
};

struct human_gait_comparison {
  gait_cycle_data cycles;           ///< the walk's curves, in the data's units
  std::vector<std::string> labels;  ///< the data's variable names, one per channel
  /// Standard score per channel; empty when the walk has no complete cycle after t_from.
  std::vector<double> scores;
  /// Mean over the cycle of the walk's mean curve minus the person's, per channel, in the data's
  /// unit (degrees, N m/kg): the sign the score lacks (a walk 10 degrees more flexed all cycle
  /// reads +10). Same points as the score; empty with it.
  std::vector<double> mean_differences;
};

/// The channels compared: human_sagittal_channels then human_sagittal_moment_channels of `side`
/// (per kg of body_mass), labelled with the data's variable names.
inline std::vector<gait_channel> human_comparison_channels(const std::string& side,
                                                           double body_mass) {
  std::vector<gait_channel> out = human_sagittal_channels(side);
  for (const gait_channel& g : human_sagittal_moment_channels(side, body_mass)) out.push_back(g);
  return out;
}

/// The comparison of the file comment. \throws std::out_of_range naming a variable the data lacks;
/// std::invalid_argument for a side other than "l" or "r", a non-finite t_from, or what
/// gait_cycles and standard_score refuse.
template <root_joint Root>
human_gait_comparison compare_with_human(const model<Root>& m, const trajectory& tr,
                                         const normative_gait& human,
                                         const human_comparison_options& o = {}) {
  check_argument(o.side == "l" || o.side == "r",
                 "compare_with_human: side must be \"l\" or \"r\", got \"", o.side, "\"");
  check_argument(std::isfinite(o.t_from), "compare_with_human: t_from is not finite");
  gait_cycle_options go;
  go.channels = human_comparison_channels(o.side, m.total_mass());
  go.side = o.side;
  go.samples = o.samples;
  go.cycle_starts = o.cycle_starts;
  human_gait_comparison out;
  std::vector<const normative_curve*> curves;
  for (const gait_channel& g : go.channels) {
    out.labels.push_back(g.label);
    curves.push_back(&human.curve(g.label));  // throws naming a missing variable
  }
  trajectory steady = tr;
  std::erase_if(steady.frames, [&](const trajectory_frame& f) { return f.t < o.t_from; });
  out.cycles = gait_cycles(m, steady, go);
  if (out.cycles.num_cycles() >= 1)
    for (std::size_t k = 0; k < curves.size(); ++k) {
      const std::vector<double>& sim = out.cycles.mean[k];
      out.scores.push_back(standard_score(out.cycles.percent, sim, *curves[k], o.samples));
      double sum = 0.0;
      for (int i = 0; i < o.samples; ++i) {
        const double p = 100.0 * i / (o.samples - 1);
        sum += detail::interpolate_curve(out.cycles.percent, sim, p) -
               detail::interpolate_curve(curves[k]->percent, curves[k]->mean, p);
      }
      out.mean_differences.push_back(sum / o.samples);
    }
  return out;
}

}  // namespace gaitsynth
