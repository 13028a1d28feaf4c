// The planar humans of Sharon & van de Panne 2005 (models/sharon2005.hpp).
#include "gaitsynth/models/sharon2005.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "models/model_checks.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

TEST_CASE("sharon2005_human7 reproduces Table I", "[models][sharon2005]") {
  const planar_model m = sharon2005_human7();
  CHECK(m.name == "sharon2005_human7");
  CHECK(m.num_bodies() == 7);
  CHECK(m.num_joint_dofs() == 6);
  CHECK(m.nq() == 9);
  CHECK(m.nv() == 9);
  const char* order[] = {"lhip", "lknee", "lankle", "rhip", "rknee", "rankle"};
  for (int j = 0; j < 6; ++j) {
    CHECK(m.dofs[j].name == order[j]);
    CHECK(m.dofs[j].axis == Eigen::Vector3d::UnitY());
    CHECK(m.dofs[j].torque_limit == 370.0);
    CHECK(m.dofs[j].limit.model == limit_model::exponential);
  }
  CHECK(m.bodies[0].name == "torso");
  // Table I: segment, mass (kg), length (m), inertia (kg m^2), printed digits.
  struct row {
    const char* body;
    double mass, length, inertia, half_unit;  // half a unit of the last printed digit
  };
  const row table[] = {{"torso", 40, 0.2, 0.1333, 5e-5},  {"lthigh", 7, 0.46, 0.1234, 5e-5},
                       {"rthigh", 7, 0.46, 0.1234, 5e-5}, {"lshin", 4, 0.44, 0.0645, 5e-5},
                       {"rshin", 4, 0.44, 0.0645, 5e-5},  {"lfoot", 2, 0.22, 0.00807, 5e-6},
                       {"rfoot", 2, 0.22, 0.00807, 5e-6}};
  for (const row& r : table) {
    INFO(r.body);
    const body& b = m.bodies[m.body_index(r.body)];
    CHECK(b.mass == r.mass);
    CHECK(b.length == r.length);
    CHECK(b.inertia(1, 1) == r.inertia);  // the in-plane (pitch) inertia is Table I's number
    // Table I's inertias are uniform rods about their centres, m L^2 / 12, to the printed digits;
    // so the COM is the rod's middle and the two link ends are the body origin and segment_end.
    CHECK(std::abs(r.mass * r.length * r.length / 12.0 - r.inertia) <= r.half_unit);
    if (std::string(r.body).find("foot") == std::string::npos) {
      CHECK(b.segment_end.norm() == Approx(r.length));
      CHECK(b.com.isApprox(0.5 * b.segment_end));
    } else {
      // The foot rod runs through the ankle from the heel (a quarter of it behind) to the toe.
      const int fb = m.body_index(r.body);
      Eigen::Vector3d heel = Eigen::Vector3d::Zero(), toe = Eigen::Vector3d::Zero();
      for (const contact_point& c : m.contact_points) {
        if (c.body != fb) continue;
        (c.role == contact_point::kind::sole ? heel : toe) = c.position;
      }
      CHECK((toe - heel).norm() == Approx(r.length));
      CHECK(heel.x() == Approx(-0.25 * r.length));
      CHECK(b.segment_end.isApprox(toe));
      CHECK(b.com.isApprox(0.5 * (heel + toe)));
    }
  }
  CHECK(m.total_mass() == 66.0);
  // Planar: everything in the x-z plane.
  for (const body& b : m.bodies) {
    CHECK(b.joint_offset.y() == 0.0);
    CHECK(b.com.y() == 0.0);
  }
}

TEST_CASE("sharon2005_human7 geometry, contacts and mirror map", "[models][sharon2005]") {
  const planar_model m = sharon2005_human7();
  // Hip 0.46 + 0.44 = 0.90 m above the foot link; torso top 0.2 m above the hip.
  CHECK(standing_height(m) == Approx(1.10).epsilon(1e-12));
  const Eigen::VectorXd q = standing_configuration(m);
  CHECK(q.size() == 9);
  CHECK(q[1] == Approx(0.90));
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::sole) == 1);
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::toe) == 1);
  }
  CHECK(m.contact_points.size() == 4);
  models_test::check_mirror(m, 3);
  for (int j = 0; j < 6; ++j) CHECK(m.mirror_sign[j] == 1.0);  // planar: +y axes, no sign flip
  models_test::check_limit_stability(m);
  // At q = 0 the whole-body COM is over the foot, more than 5 cm inside the heel: it can stand.
  const Eigen::Vector3d c = models_test::neutral_com(m);
  CHECK(c.x() > -0.055 + 0.05);
  CHECK(c.x() < 0.165);
  sharon2005_human7_parameters p;
  p.heel_behind_ankle = 0.0;  // the ankle at the heel end of the foot
  const planar_model at_heel = sharon2005_human7(p);
  CHECK(at_heel.contact_points[0].position.x() == 0.0);
  CHECK(at_heel.bodies[at_heel.body_index("lfoot")].segment_end.x() == Approx(0.22));
  p.heel_behind_ankle = 1.5;
  CHECK_THROWS_WITH(sharon2005_human7(p), Catch::Matchers::Contains("heel_behind_ankle"));
}

TEST_CASE("sharon2005_human7 parameters (Fig. 8 robustness variants)", "[models][sharon2005]") {
  sharon2005_human7_parameters p;
  p.torso_mass = 28.0;
  const planar_model light = sharon2005_human7(p);
  CHECK(light.total_mass() == 54.0);
  CHECK(light.bodies[0].inertia(1, 1) == 0.1333);  // unchanged unless asked
  const planar_model rods = sharon2005_human7(p.with_rod_inertias());
  CHECK(rods.bodies[0].inertia(1, 1) == Approx(28.0 * 0.04 / 12.0));
  p = {};
  p.shin_length = 0.25;
  p.thigh_length = 0.6;
  const planar_model legs = sharon2005_human7(p.with_rod_inertias());
  CHECK(standing_height(legs) == Approx(1.05));
  CHECK(legs.bodies[legs.body_index("lthigh")].inertia(1, 1) == Approx(7.0 * 0.36 / 12.0));

  const double nan = std::numeric_limits<double>::quiet_NaN();
  p = {};
  p.thigh_length = -0.46;
  CHECK_THROWS_AS(sharon2005_human7(p), std::invalid_argument);
  CHECK_THROWS_WITH(sharon2005_human7(p), Contains("thigh_length") && Contains("-0.46"));
  p = {};
  p.torso_mass = nan;
  CHECK_THROWS_WITH(sharon2005_human7(p), Contains("torso_mass") && Contains("nan"));
  p = {};
  p.foot_inertia = 0.0;
  CHECK_THROWS_WITH(sharon2005_human7(p), Contains("foot_inertia"));
}

TEST_CASE("sharon2005_human16 from de Leva's table", "[models][sharon2005]") {
  const planar_model m = sharon2005_human16();
  CHECK(m.name == "sharon2005_human16");
  CHECK(m.num_bodies() == 16);
  CHECK(m.num_joint_dofs() == 15);
  const char* order[] = {"lhip",   "lknee",  "lankle",    "rhip",   "rknee",
                         "rankle", "back",   "chest",     "neck",   "lshoulder",
                         "lelbow", "lwrist", "rshoulder", "relbow", "rwrist"};
  for (int j = 0; j < 15; ++j) {
    CHECK(m.dofs[j].name == order[j]);
    CHECK(m.dofs[j].axis == Eigen::Vector3d::UnitY());
  }
  for (const char* d : {"lhip", "lknee", "lankle", "rhip", "rknee", "rankle"})
    CHECK(m.dofs[m.dof_index(d)].torque_limit == 370.0);
  CHECK(m.total_mass() == Approx(73.0).epsilon(1e-12));
  CHECK(standing_height(m) == Approx(1.741).epsilon(1e-12));
  // Masses are de Leva's percentages of 73 kg (Table 4, male).
  CHECK(m.bodies[m.body_index("lthigh")].mass == Approx(0.1416 * 73.0));
  CHECK(m.bodies[m.body_index("head")].mass == Approx(0.0694 * 73.0));
  CHECK(m.bodies[m.body_index("pelvis")].mass == Approx(0.1117 * 73.0));
  CHECK(m.bodies[m.body_index("rhand")].mass == Approx(0.0061 * 73.0));
  // Lengths are de Leva's times one factor (vertical chain = stature), radii of gyration his.
  const double s = 1.741 / 1.7087;
  const body& th = m.bodies[m.body_index("lthigh")];
  CHECK(th.length == Approx(0.4222 * s));
  CHECK(th.com.z() == Approx(-0.4095 * 0.4222 * s));
  CHECK(th.inertia(1, 1) == Approx(th.mass * std::pow(0.329 * th.length, 2)));
  CHECK(th.inertia(2, 2) == Approx(th.mass * std::pow(0.149 * th.length, 2)));
  const body& ft = m.bodies[m.body_index("lfoot")];
  CHECK(ft.segment_end.x() == Approx(0.75 * 0.2581 * s));
  CHECK(ft.com.x() == Approx((0.4415 - 0.25) * 0.2581 * s));
  // A standing human's COM is at about 55-57 % of stature (e.g. Winter 2009); feet flat under it.
  const Eigen::Vector3d c = models_test::neutral_com(m);
  CHECK((c.z() - neutral_lowest_contact(m)) / 1.741 == Approx(0.56).margin(0.02));
  models_test::check_mirror(m, 6);
  models_test::check_limit_stability(m);
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::sole) == 1);
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::toe) == 1);
  }
}

TEST_CASE("sharon2005_human16 scales with height and mass", "[models][sharon2005]") {
  const planar_model m = sharon2005_human16({.height = 1.5, .mass = 50.0});
  CHECK(m.total_mass() == Approx(50.0).epsilon(1e-12));
  CHECK(standing_height(m) == Approx(1.5).epsilon(1e-12));
  models_test::check_limit_stability(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(sharon2005_human16({.height = 0.0}), Contains("height") && Contains("got 0"));
  CHECK_THROWS_WITH(sharon2005_human16({.height = 1.7, .mass = nan}),
                    Contains("mass") && Contains("nan"));
  CHECK_THROWS_AS(sharon2005_human16({.height = 1.7, .mass = -70.0}), std::invalid_argument);
}
