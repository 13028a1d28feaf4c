// The humanoid of Wang et al. 2012 (models/wang2012.hpp).
#include "gaitsynth/models/wang2012.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "gaitsynth/models/wang2009.hpp"
#include "models/model_checks.hpp"

using namespace gaitsynth;

TEST_CASE("wang2012_humanoid: 180 cm, 70 kg, 30 DOFs", "[models][wang2012]") {
  const floating_model m = wang2012_humanoid();
  CHECK(m.name == "wang2012_humanoid");
  CHECK(m.num_joint_dofs() == 30);
  CHECK(m.nv() == 36);
  CHECK(m.total_mass() == Approx(70.0).epsilon(1e-12));
  CHECK(standing_height(m) == Approx(1.80).epsilon(1e-12));
  // Same DOFs, in the same order, as the Wang 2009 character.
  const floating_model w = wang2009_humanoid();
  for (int j = 0; j < 30; ++j) {
    CHECK(m.dofs[j].name == w.dofs[j].name);
    CHECK(m.dofs[j].axis == w.dofs[j].axis);
  }
  models_test::check_mirror(m, 12);
  models_test::check_limit_stability(m);
}

TEST_CASE("wang2012_humanoid has the Wang 2009 body contact points", "[models][wang2012]") {
  // Same builder: 43 points of role other on the trunk, head, arms and legs (tests/models/
  // wang2009.cpp checks where), after the 36 foot and toe points, none within 0.2 H of the sole
  // plane at q = 0; every body has at least one point.
  const floating_model m = wang2012_humanoid();
  const floating_model w = wang2009_humanoid(wang2009_body{.height = 1.8, .mass = 70});
  REQUIRE(m.contact_points.size() == 36 + 43);
  const auto o = neutral_body_origins(m);
  const double ground = neutral_lowest_contact(m);
  std::vector<int> per_body(m.bodies.size(), 0);
  std::size_t k = 0;
  for (const contact_point& c : m.contact_points) {
    INFO(c.name);
    ++per_body[c.body];
    CHECK((c.role == contact_point::kind::other) == (k++ >= 36));
    if (c.role != contact_point::kind::other) continue;
    CHECK(o[c.body].z() + c.position.z() - ground >= 0.2 * 1.8);
    // The Wang 2009 character of the same size has the same point.
    const auto it = std::find_if(w.contact_points.begin(), w.contact_points.end(),
                                 [&](const contact_point& e) { return e.name == c.name; });
    REQUIRE(it != w.contact_points.end());
    CHECK(it->body == c.body);
    CHECK(it->position.isApprox(c.position, 1e-12));
  }
  for (std::size_t b = 0; b < m.bodies.size(); ++b) CHECK(per_body[b] >= 1);
}

TEST_CASE("wang2012_humanoid Geyer-Herr soft limits", "[models][wang2012]") {
  const floating_model m = wang2012_humanoid();
  const double deg = std::numbers::pi / 180.0;
  for (const char* S : {"l", "r"}) {
    const std::string s = S;
    const joint_limit& hip = m.dofs[m.dof_index(s + "hip_y")].limit;
    const joint_limit& knee = m.dofs[m.dof_index(s + "knee")].limit;
    const joint_limit& ankle = m.dofs[m.dof_index(s + "ankle_y")].limit;
    CHECK(hip.upper == Approx(50 * deg));     // 230 deg hip angle
    CHECK(knee.lower == Approx(5 * deg));     // 175 deg knee angle
    CHECK(ankle.lower == Approx(-20 * deg));  // 70 deg shank-foot angle
    CHECK(ankle.upper == Approx(40 * deg));   // 130 deg
    for (const joint_limit* L : {&hip, &knee, &ankle}) {
      CHECK(L->model == limit_model::spring_damper);
      CHECK(L->stiffness == Approx(0.3 * 180.0 / std::numbers::pi));  // 0.3 N m / deg
    }
    // The coronal and transverse DOFs keep the Wang 2009 limits.
    CHECK(m.dofs[m.dof_index(s + "hip_x")].limit.stiffness > 100.0);
  }
}

TEST_CASE("wang2012_humanoid heel and ball cylinders", "[models][wang2012]") {
  const floating_model m = wang2012_humanoid();
  const auto o = neutral_body_origins(m);
  const double ground = neutral_lowest_contact(m);
  for (const char* S : {"l", "r"}) {
    const std::string s = S;
    CHECK(models_test::count_contacts(m, s + "foot", contact_point::kind::sole) == 12);
    CHECK(models_test::count_contacts(m, s + "toes", contact_point::kind::toe) == 4);
    CHECK(models_test::count_contacts(m, s + "toes", contact_point::kind::toe_top) == 2);
    // Sole points lie on the two cylinders (shapes 1 and 2 of the foot); the lowest ones touch
    // the ground plane at q = 0.
    const body& foot = m.bodies[m.body_index(s + "foot")];
    REQUIRE(foot.shapes.size() == 3);
    int on_ground = 0;
    for (const contact_point& c : m.contact_points) {
      if (c.body != m.body_index(s + "foot")) continue;
      double dmin = 1e9;
      for (int k = 1; k <= 2; ++k) {
        const shape& cyl = foot.shapes[k];
        CHECK(cyl.type == shape::kind::capsule);
        const Eigen::Vector2d d(c.position.x() - cyl.p0.x(), c.position.z() - cyl.p0.z());
        dmin = std::min(dmin, std::abs(d.norm() - cyl.radius));
      }
      CHECK(dmin < 1e-12);
      on_ground += std::abs(o[c.body].z() + c.position.z() - ground) < 1e-12;
    }
    CHECK(on_ground == 4);
  }
  CHECK(wang2012_passive::toe_stiffness == 30.0);
}
