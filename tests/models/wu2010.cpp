// The biped of Wu & Popovic 2010 (models/wu2010.hpp).
#include "gaitsynth/models/wu2010.hpp"

#include <catch2/catch.hpp>
#include <limits>

#include "models/model_checks.hpp"

using namespace gaitsynth;

TEST_CASE("wu2010_biped reproduces Table 3", "[models][wu2010]") {
  const floating_model m = wu2010_biped();
  CHECK(m.name == "wu2010_biped");
  CHECK(m.num_bodies() == 8);
  CHECK(m.num_joint_dofs() == 17);
  CHECK(m.nv() == 23);
  const char* order[] = {"lhip_x",   "lhip_y",   "lhip_z",  "lknee",   "lankle_x", "lankle_y",
                         "lankle_z", "rhip_x",   "rhip_y",  "rhip_z",  "rknee",    "rankle_x",
                         "rankle_y", "rankle_z", "waist_x", "waist_y", "waist_z"};
  for (int j = 0; j < 17; ++j) CHECK(m.dofs[j].name == order[j]);
  // Table 3: mass (kg), principal inertias (kg m^2), length (m), tau_max (N m) of its joint.
  struct row {
    const char* body;
    double mass;
    Eigen::Vector3d I;
    double length;
  };
  const row table[] = {{"upper_body", 40, {1, 1, 0.1}, 0.8},
                       {"hip", 8.8, {0.1, 0.1, 0.1}, 0.3},  // radius 0.15
                       {"lthigh", 8.552, {0.1, 0.1, 0.05}, 0.5},
                       {"rthigh", 8.552, {0.1, 0.1, 0.05}, 0.5},
                       {"lshank", 4.352, {0.04, 0.04, 0.01}, 0.55},
                       {"rshank", 4.352, {0.04, 0.04, 0.01}, 0.55},
                       // Table 3 lists (0.03, 0.001, 0.03) with y along the foot; ours is x.
                       {"lfoot", 1, {0.001, 0.03, 0.03}, 0.25},
                       {"rfoot", 1, {0.001, 0.03, 0.03}, 0.25}};
  for (const row& r : table) {
    INFO(r.body);
    const body& b = m.bodies[m.body_index(r.body)];
    CHECK(b.mass == r.mass);
    CHECK(b.inertia == Eigen::Matrix3d(r.I.asDiagonal()));
    CHECK(b.length == r.length);
  }
  CHECK(m.total_mass() == Approx(76.608).epsilon(1e-14));
  // Joint torque limits: waist 1600, knee 700, ankle 400; hip 700 (our assumption).
  CHECK(m.dofs[m.dof_index("waist_y")].torque_limit == 1600);
  CHECK(m.dofs[m.dof_index("rknee")].torque_limit == 700);
  CHECK(m.dofs[m.dof_index("lankle_z")].torque_limit == 400);
  CHECK(m.dofs[m.dof_index("lhip_y")].torque_limit == 700);
  // Joint types: spherical waist, hips and ankles (3 DOFs), revolute knees.
  CHECK(m.bodies[m.body_index("upper_body")].num_dofs == 3);
  CHECK(m.bodies[m.body_index("lthigh")].num_dofs == 3);
  CHECK(m.bodies[m.body_index("lshank")].num_dofs == 1);
  CHECK(m.bodies[m.body_index("lfoot")].num_dofs == 3);
}

TEST_CASE("wu2010_biped contacts, mirror map and limits", "[models][wu2010]") {
  const floating_model m = wu2010_biped();
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::sole) == 4);
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::toe) == 4);
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::toe_top) == 2);
  }
  // Heel and toe boxes with a gap between them (Fig. 9): no contact point in the gap.
  const auto o = neutral_body_origins(m);
  const double ground = neutral_lowest_contact(m);
  double heel_front = -1e9, toe_back = 1e9;
  for (const contact_point& c : m.contact_points) {
    if (c.role == contact_point::kind::toe_top) continue;
    CHECK(o[c.body].z() + c.position.z() == Approx(ground));
    if (c.role == contact_point::kind::sole) heel_front = std::max(heel_front, c.position.x());
    if (c.role == contact_point::kind::toe) toe_back = std::min(toe_back, c.position.x());
  }
  CHECK(toe_back - heel_front == Approx(0.05));
  CHECK(standing_height(m) == Approx(1.91));
  models_test::check_mirror(m, 7);
  models_test::check_limit_stability(m);
}

TEST_CASE("wu2010_biped's Section 9 variants: inverted knees, a frozen left knee",
          "[models][wu2010]") {
  const floating_model normal = wu2010_biped();
  const floating_model inv = wu2010_biped({.knees = wu2010_knees::inverted});
  CHECK(inv.name == "wu2010_biped_inverted_knees");
  for (const char* k : {"lknee", "rknee"}) {
    INFO(k);
    const joint_limit& a = normal.dofs[normal.dof_index(k)].limit;
    const joint_limit& b = inv.dofs[inv.dof_index(k)].limit;
    CHECK(a.lower == 0.0);
    CHECK(a.upper == Approx(2.4));
    CHECK(b.lower == -a.upper);  // the same range, bending forward
    CHECK(b.upper == -a.lower);
    CHECK(b.stiffness == a.stiffness);
    CHECK(b.damping == a.damping);
  }
  CHECK(inv.total_mass() == normal.total_mass());
  models_test::check_mirror(inv, 7);
  models_test::check_limit_stability(inv);

  const floating_model frozen = wu2010_biped({.frozen_left_knee = true, .frozen_knee_angle = 0.1});
  CHECK(frozen.name == "wu2010_biped_frozen_left_knee");
  const joint_limit& lk = frozen.dofs[frozen.dof_index("lknee")].limit;
  const joint_limit& nk = normal.dofs[normal.dof_index("lknee")].limit;
  CHECK(lk.lower == 0.1);
  CHECK(lk.upper == 0.1);
  CHECK(lk.stiffness == Approx(100 * nk.stiffness));
  CHECK(lk.damping == Approx(10 * nk.damping));
  // 700 N m, the knee's torque limit, deflects it by less than 6 mrad.
  CHECK(700.0 / lk.stiffness < 0.006);
  const joint_limit& rk = frozen.dofs[frozen.dof_index("rknee")].limit;
  CHECK(rk.lower == nk.lower);
  CHECK(rk.upper == nk.upper);
  CHECK(rk.stiffness == nk.stiffness);
  models_test::check_limit_stability(frozen);
  CHECK(wu2010_biped({.knees = wu2010_knees::inverted, .frozen_left_knee = true}).name ==
        "wu2010_biped_inverted_knees_frozen_left_knee");

  // A frozen angle outside the knee's range, or a bad factor, is refused with the value named.
  CHECK_THROWS_WITH(wu2010_biped({.frozen_left_knee = true, .frozen_knee_angle = -0.2}),
                    Catch::Contains("frozen_knee_angle") && Catch::Contains("-0.2"));
  CHECK_THROWS_WITH(
      wu2010_biped(
          {.knees = wu2010_knees::inverted, .frozen_left_knee = true, .frozen_knee_angle = 0.2}),
      Catch::Contains("frozen_knee_angle") && Catch::Contains("0.2"));
  CHECK_THROWS_WITH(wu2010_biped({.frozen_left_knee = true, .frozen_stiffness_factor = 0.0}),
                    Catch::Contains("frozen_stiffness_factor"));
  CHECK_THROWS_WITH(
      wu2010_biped({.frozen_left_knee = true,
                    .frozen_damping_factor = std::numeric_limits<double>::quiet_NaN()}),
      Catch::Contains("frozen_damping_factor") && Catch::Contains("nan"));
}
