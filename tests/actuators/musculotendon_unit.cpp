// One Hill-type MTU (actuators/musculotendon/): the Geyer & Herr 2010 curves at points computed
// by hand from the published formulas, isometric force at the optimal length, tendon force at the
// reference strain, isokinetic contractions that follow Hill's hyperbola, the activation's step
// response (10 ms), and the energy of a passive stretch-and-release.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gaitsynth/actuators/musculotendon/contraction.hpp"
#include "gaitsynth/actuators/musculotendon/hill_curves.hpp"

using namespace gaitsynth::musculotendon;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// Geyer & Herr 2010 Table I: SOL (the slow muscle, vmax 6) and VAS.
const unit_parameters soleus{4000.0, 0.04, 0.26, 6.0};
const unit_parameters vasti{6000.0, 0.08, 0.23, 12.0};
constexpr double h = 1.0 / 2400.0;

}  // namespace

TEST_CASE("force-length: 1 at l_opt, 0.05 at l_opt (1 +- w), 0.05^(1/8) half-way",
          "[actuators][musculotendon]") {
  CHECK(force_length(1.0) == 1.0);
  CHECK_THAT(force_length(1.56), WithinRel(0.05, 1e-12));
  CHECK_THAT(force_length(0.44), WithinRel(0.05, 1e-12));
  // |x| = 1/2: exp(ln 0.05 / 8) = 0.05^(1/8) = 0.687656...
  CHECK_THAT(force_length(1.28), WithinRel(0.6876560, 1e-6));
  CHECK_THAT(force_length(0.72), WithinRel(std::pow(0.05, 0.125), 1e-12));
}

TEST_CASE("force_length_with_slope: f_L to the bit with one exp, and its slope by differences",
          "[actuators][musculotendon]") {
  for (double l : {0.3, 0.44, 0.72, 0.99, 1.0, 1.01, 1.28, 1.56, 1.9}) {
    INFO("l " << l);
    const force_length_and_slope f = force_length_with_slope(l);
    CHECK(f.value == force_length(l));
    CHECK(f.slope == force_length_slope(l));
    const double e = 1e-7;
    const double fd = (force_length(l + e) - force_length(l - e)) / (2.0 * e);
    CHECK_THAT(f.slope, WithinAbs(fd, 1e-7 * (1.0 + std::abs(fd))));
  }
  CHECK(force_length_with_slope(1.0).slope == 0.0);  // the curve's top
  CHECK(force_length_with_slope(1.28).slope < 0.0);
  CHECK(force_length_with_slope(0.72).slope > 0.0);
}

TEST_CASE("force-velocity: Hill's hyperbola when shortening, the eccentric branch when lengthening",
          "[actuators][musculotendon]") {
  const double V = 6.0;  // l_opt / s
  CHECK(force_velocity(0.0, V) == 1.0);
  CHECK(force_velocity(-V, V) == 0.0);
  // v = -V/2: (V/2) / (V + 5 V/2) = 1/7
  CHECK_THAT(force_velocity(-0.5 * V, V), WithinRel(1.0 / 7.0, 1e-14));
  // v = +V: N + (N - 1) * 0 = 1.5; v = V/2: 1.5 - 0.25 / 19.9
  CHECK_THAT(force_velocity(V, V), WithinRel(1.5, 1e-14));
  CHECK_THAT(force_velocity(0.5 * V, V), WithinRel(1.5 - 0.25 / 19.9, 1e-14));
  CHECK(force_velocity(1e9, V) < force_velocity_limit);
  CHECK_THAT(force_velocity(1e9, V), WithinRel(force_velocity_limit, 1e-6));
  // Continuous at 0 with slopes (1 + K) / V (shortening) and (N - 1)(1 + 7.56 K) / V.
  const double e = 1e-7;
  CHECK_THAT((1.0 - force_velocity(-e, V)) / e, WithinRel(6.0 / V, 1e-5));
  CHECK_THAT((force_velocity(e, V) - 1.0) / e, WithinRel(0.5 * 38.8 / V, 1e-5));
  for (double v : {-5.9, -3.0, -0.1, 0.0, 0.2, 4.0, 50.0})
    CHECK_THAT(fiber_velocity(force_velocity(v, V), V), WithinAbs(v, 1e-9 * (1.0 + std::abs(v))));
}

TEST_CASE("tendon, parallel and buffer elements: quadratic springs with Geyer & Herr's references",
          "[actuators][musculotendon]") {
  CHECK(tendon_force(0.04) == 1.0);  // the reference strain carries F_max
  CHECK_THAT(tendon_force(0.02), WithinRel(0.25, 1e-14));
  CHECK(tendon_force(-0.01) == 0.0);
  CHECK_THAT(tendon_stiffness(0.02), WithinRel((tendon_force(0.02 + 1e-8) - 0.25) / 1e-8, 1e-6));
  CHECK(parallel_force(1.0) == 0.0);
  CHECK_THAT(parallel_force(1.56), WithinRel(1.0, 1e-14));
  CHECK(buffer_force(0.44) == 0.0);
  CHECK_THAT(buffer_force(0.16), WithinRel(1.0, 1e-12));  // (0.44 - 0.16) / 0.28 = 1
}

TEST_CASE("isometric at l_opt with full activation: the MTU force is F_max, the fiber is still",
          "[actuators][musculotendon]") {
  for (const unit_parameters& p : {soleus, vasti}) {
    const double l_mtu = p.optimal_fiber_length + p.tendon_slack_length * 1.04;
    const element_forces f = forces_at(p, l_mtu, p.optimal_fiber_length);
    CHECK_THAT(f.tendon, WithinRel(p.max_isometric_force, 1e-12));
    CHECK(f.parallel == 0.0);
    CHECK(f.buffer == 0.0);
    CHECK_THAT(equilibrium_velocity(p, 1.0, l_mtu, p.optimal_fiber_length), WithinAbs(0.0, 1e-12));
    CHECK_THAT(isometric_fiber_length(p, 1.0, l_mtu), WithinAbs(p.optimal_fiber_length, 1e-12));
    // Half activation: the fiber lengthens and the tendon unloads until they balance.
    const double l_half = isometric_fiber_length(p, 0.5, l_mtu);
    const element_forces g = forces_at(p, l_mtu, l_half);
    CHECK(l_half > p.optimal_fiber_length);
    CHECK_THAT(g.tendon, WithinRel(0.5 * p.max_isometric_force *
                                           force_length(l_half / p.optimal_fiber_length) +
                                       g.parallel,
                                   1e-9));
  }
}

TEST_CASE("isokinetic contractions follow Hill's force-velocity curve",
          "[actuators][musculotendon]") {
  // A fully active SOL whose MTU shortens or lengthens at a constant speed, started in the
  // steady state that Hill's hyperbola (written out below, not the library's f_V) predicts: the
  // fiber at the ramp's speed, the tendon stretched to carry F_max f_L hill. If the model follows
  // the hyperbola, the fiber keeps the ramp's speed and the force stays there.
  const unit_parameters& p = soleus;
  const double lo = p.optimal_fiber_length, ls = p.tendon_slack_length;
  const double V = p.max_shortening_velocity;
  for (double vn : {-0.75, -0.5, -0.25, -0.1, 0.1, 0.25, 0.5}) {
    // (1 + vn) / (1 - K vn) shortening; N + (N - 1)(vn - 1) / (7.56 K vn + 1) lengthening.
    const double hill =
        vn < 0.0 ? (1.0 + vn) / (1.0 - 5.0 * vn) : 1.5 + 0.5 * (vn - 1.0) / (37.8 * vn + 1.0);
    const double v = vn * V * lo;  // m/s
    // The fiber moves through [0.96, 1] l_opt, where f_L is within 0.11 % of 1 and the parallel
    // element is slack, so that the steady state stays (nearly) steady.
    const double t_half = 0.02 * lo / std::abs(v);
    double l_ce = vn < 0.0 ? lo : 0.96 * lo;
    auto tendon_for = [&](double l) {  // the tendon length that carries the predicted force
      const double f = force_length(l / lo) * hill + parallel_force(l / lo);
      return ls * (1.0 + 0.04 * std::sqrt(f));
    };
    double l_mtu = l_ce + tendon_for(l_ce);
    const int n = static_cast<int>(2.0 * t_half / h);
    double worst_v = 0.0, worst_f = 0.0;
    for (int k = 0; k < n; ++k) {
      l_mtu += v * h;
      const double l_new = advance_fiber(p, 1.0, l_mtu, l_ce, h);
      const double v_ce = (l_new - l_ce) / h;
      l_ce = l_new;
      const double force = forces_at(p, l_mtu, l_ce).tendon / p.max_isometric_force;
      const double predicted = force_length(l_ce / lo) * hill + parallel_force(l_ce / lo);
      worst_v = std::max(worst_v, std::abs(v_ce / v - 1.0));
      worst_f = std::max(worst_f, std::abs(force / predicted - 1.0));
    }
    INFO("ramp at " << vn << " vmax over " << n << " steps: fiber speed off by " << worst_v
                    << ", force off by " << worst_f);
    // The force to 0.1 %; the speed to 1 %: f_L still varies by 0.11 % over the ramp, and the
    // eccentric branch is so flat that this moves a lengthening fiber's speed by up to 0.9 %.
    CHECK(worst_v < 0.01);
    CHECK(worst_f < 0.001);
  }
}

TEST_CASE("activation: a first-order step response with a 10 ms time constant",
          "[actuators][musculotendon]") {
  double a = 0.0;
  for (int k = 0; k < 24; ++k) a = advance_activation(a, 1.0, h);  // 10 ms at 2400 Hz
  CHECK_THAT(a, WithinRel(1.0 - std::pow(1.0 - 1.0 / 24.0, 24), 1e-12));
  CHECK_THAT(a, WithinRel(1.0 - std::exp(-1.0), 0.015));  // the continuous law's 63.2 %
  for (int k = 0; k < 24 * 10; ++k) a = advance_activation(a, 1.0, h);
  CHECK(a > 0.9999);
  CHECK(a <= 1.0);
  // Excitations outside [0, 1] are clamped: the activation never leaves [0, 1].
  CHECK(advance_activation(1.0, 7.0, h) == 1.0);
  CHECK(advance_activation(0.0, -3.0, h) == 0.0);
}

TEST_CASE(
    "a passive stretch and release: the work put in is the elastic energy plus what the "
    "fiber absorbs, and the passive MTU returns no more than it took",
    "[actuators][musculotendon]") {
  const unit_parameters& p = vasti;
  const double lo = p.optimal_fiber_length, ls = p.tendon_slack_length;
  const double a = 0.0;  // passive (the fiber's velocity is computed at the minimum activation)
  auto elastic_energy = [&](double l_mtu, double l_ce) {  // integrals of the quadratic springs
    const double e = std::max((l_mtu - l_ce - ls) / ls, 0.0);
    const double x = std::max(l_ce / lo - 1.0, 0.0);
    const double b = std::max(hill_constants::buffer_length - l_ce / lo, 0.0);
    return p.max_isometric_force *
           (ls * e * e * e / (3.0 * 0.04 * 0.04) + lo * x * x * x / (3.0 * 0.56 * 0.56) +
            lo * b * b * b / (3.0 * 0.28 * 0.28));
  };
  const double l0 = lo * 1.3 + ls;  // a stretched start
  double l_mtu = l0;
  double l_ce = isometric_fiber_length(p, a, l_mtu);
  const double e0 = elastic_energy(l_mtu, l_ce);
  double work_in = 0.0, fiber_work_absorbed = 0.0;
  const int n = static_cast<int>(2.0 / h);
  for (int k = 0; k < n; ++k) {  // one cycle of 4 cm amplitude, 2 s
    const double t1 = (k + 1) * h;
    const double l_next = l0 + 0.04 * std::sin(std::numbers::pi * t1);
    const element_forces f0 = forces_at(p, l_mtu, l_ce);
    const double l_ce_next = advance_fiber(p, a, l_next, l_ce, h);
    const element_forces f1 = forces_at(p, l_next, l_ce_next);
    work_in += 0.5 * (f0.tendon + f1.tendon) * (l_next - l_mtu);
    fiber_work_absorbed += 0.5 * (f0.contractile() + f1.contractile()) * (l_ce_next - l_ce);
    l_mtu = l_next;
    l_ce = l_ce_next;
  }
  const double e1 = elastic_energy(l_mtu, l_ce);
  INFO("work in " << work_in << " J, elastic " << e1 - e0 << " J, fiber absorbed "
                  << fiber_work_absorbed << " J");
  // Bookkeeping: what the environment put in is stored or absorbed (trapezoid rule, 1 %).
  CHECK_THAT(work_in, WithinAbs((e1 - e0) + fiber_work_absorbed, 0.01 * std::abs(work_in) + 1e-6));
  // Over the closed cycle the passive MTU gave back no more than it took.
  CHECK(work_in >= 0.0);
  CHECK(fiber_work_absorbed >= 0.0);
}

TEST_CASE(
    "the analytic slope of the equilibrium velocity matches finite differences, and the "
    "fiber step does not depend on its starting guess",
    "[actuators][musculotendon]") {
  for (const unit_parameters& p : {soleus, vasti}) {
    const double lo = p.optimal_fiber_length, ls = p.tendon_slack_length;
    int checked = 0;
    for (double a : {0.0, 0.05, 0.5, 1.0})
      for (double strain : {0.005, 0.02, 0.05})
        for (double l : {0.5, 0.8, 0.97, 1.1, 1.3}) {
          const double l_ce = l * lo, l_mtu = l_ce + ls * (1.0 + strain);
          const auto vs = equilibrium_velocity_and_slope(p, a, l_mtu, l_ce);
          const double e = 1e-7 * lo;
          const double up = equilibrium_velocity(p, a, l_mtu, l_ce + e);
          const double down = equilibrium_velocity(p, a, l_mtu, l_ce - e);
          INFO("a " << a << ", strain " << strain << ", l " << l);
          // The step from a poor guess (the velocity bound) ends where the warm start ends.
          const double warm = advance_fiber(p, a, l_mtu, l_ce, h, vs.velocity);
          const double cold = advance_fiber(p, a, l_mtu, l_ce, h, -p.max_shortening_velocity * lo);
          CHECK_THAT(warm, WithinAbs(cold, 1e-11 * lo));
          CHECK_THAT(warm, WithinAbs(advance_fiber(p, a, l_mtu, l_ce, h), 1e-11 * lo));
          if (vs.slope == 0.0) continue;  // a guard clamps the ratio here: no slope to check
          ++checked;
          CHECK_THAT(vs.slope, WithinRel((up - down) / (2 * e), 1e-5));
        }
    CHECK(checked >= 12);  // of 60: the others ask more than the fiber can give (clamped)
  }
}

TEST_CASE("a slack tendon and a collapsed fiber give finite, bounded velocities",
          "[actuators][musculotendon][bad_input]") {
  const unit_parameters& p = vasti;
  for (double l_mtu : {0.05, 0.2, 0.31, 0.5, 2.0})
    for (double l_ce : {0.001, 0.03, 0.08, 0.2, 0.6})
      for (double a : {0.0, 0.01, 1.0}) {
        const double v = equilibrium_velocity(p, a, l_mtu, l_ce);
        CHECK(std::isfinite(v));
        CHECK(v >= -p.max_shortening_velocity * p.optimal_fiber_length * (1 + 1e-12));
        CHECK(v <= 10.0 * p.max_shortening_velocity * p.optimal_fiber_length * (1 + 1e-12));
        CHECK(std::isfinite(advance_fiber(p, a, l_mtu, l_ce, h)));
      }
}
