// Which controller rates hold Wu & Popovic 2010's lower level (docs/reproductions/wu2010.md,
// "Controller rate"): 3 s of standing_balance and 10 s of planned_walk (the middle of Table 1's
// bounds, a 400 N helper force) at 2400, 600, 240, 120 and 64 Hz, the command held between the
// 2400 Hz physics steps, with the default gains and with all gains low (the null-space damper at
// its default, 60 1/s, in both). Prints each rollout's stop reason, time and distance.
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_controller_rates.cpp -o /tmp/rates && /tmp/rates
//
// (one command line).
#include <cstdio>
#include <string>
#include <vector>

#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/wu2010.hpp"

using namespace gaitsynth;

namespace {
/// The "all gains low" variant of the doc's table.
end_effector_gains low_gains(end_effector_gains g) {
  g.ub_ko = 300;
  g.ub_bo = 5;
  g.ub_kp = 600;
  g.ub_bp = 60;
  g.ankle_kp = 400;
  g.ankle_bp = 20;
  g.toe_heel_kr = 400;
  g.toe_heel_br = 2;
  return g;
}

void print(const char* what, double hz, const char* variant, const rollout_result& r) {
  std::printf("%-9s %6.0f Hz  %-22s %-10s %6.3f s  %6.2f m\n", what, hz, variant,
              std::string(to_string(r.reason)).c_str(), r.time,
              r.com_final.x() - r.com_initial.x());
}
}  // namespace

int main() {
  const floating_model m = wu2010_biped();
  auto scratch = make_rollout_scratch(m);
  const std::vector<double> rates{2400.0, 600.0, 240.0, 120.0, 64.0};
  for (double hz : rates) {
    const double period = hz >= 2400.0 ? 0.0 : 1.0 / hz;
    struct variant {
      const char* name;
      end_effector_gains gains;
    };
    const end_effector_gains d;
    for (const variant& v : {variant{"default", d}, variant{"all gains low", low_gains(d)}}) {
      standing_balance_options o;
      o.period = period;
      standing_balance<> c(m, o, v.gains);
      rollout_options opt;
      opt.duration = 3.0;
      const auto p = v.gains.to_array();
      print("standing", hz, v.name,
            rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain(),
                    semi_implicit_euler(), p, opt, scratch));
    }
    for (int low = 0; low < 2; ++low) {
      planned_walk_options po;
      po.helper_force = true;
      po.period = period;
      planned_walk<> c(m, flat_terrain{}, po);
      const std::vector<std::string> names = c.parameter_names();
      std::vector<double> x;
      for (const parameter_spec& s : wu2010_search_space(c, c.default_parameters()).parameters())
        x.push_back(0.5 * (s.lower + s.upper));
      x.back() = 400.0;  // h_max
      if (low) {
        const end_effector_gains g = low_gains({});
        const auto values = g.to_array();
        const auto defaults = end_effector_gains{}.to_array();
        for (std::size_t i = 0; i < names.size(); ++i)
          for (std::size_t k = 0; k < end_effector_gains::size; ++k) {
            const std::string tail = std::string(".") + end_effector_gains::names[k];
            const bool tuned = values[k] != defaults[k];  // a gain low_gains() changes
            if (tuned && names[i].size() > tail.size() &&
                names[i].compare(names[i].size() - tail.size(), tail.size(), tail) == 0)
              x[i] = values[k];
          }
      }
      rollout_options opt;
      opt.duration = 10.0;
      print("walking", hz, low ? "all gains low" : "middle of the bounds",
            rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain(),
                    semi_implicit_euler(), std::span<const double>(x), opt, scratch));
    }
  }
}
