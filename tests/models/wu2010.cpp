// The biped of Wu & Popovic 2010 (models/wu2010.hpp).
#include "gaitsynth/models/wu2010.hpp"

#include <catch2/catch.hpp>

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
