// The 3D humanoid of Wang et al. 2009 (models/wang2009.hpp).
#include "gaitsynth/models/wang2009.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "models/model_checks.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

TEST_CASE("wang2009_humanoid has the paper's 30 DOFs", "[models][wang2009]") {
  const floating_model m = wang2009_humanoid();
  CHECK(m.name == "wang2009_stocky");
  CHECK(wang2009_humanoid({}).name == "wang2009_stocky");  // {} is the default body, not a preset
  CHECK(m.num_joint_dofs() == 30);
  CHECK(m.nv() == 36);
  CHECK(m.nq() == 37);
  CHECK(m.num_bodies() == 15);
  const char* order[] = {"lhip_x",      "lhip_y",      "lhip_z",      "lknee",    "lankle_x",
                         "lankle_y",    "ltoe",        "rhip_x",      "rhip_y",   "rhip_z",
                         "rknee",       "rankle_x",    "rankle_y",    "rtoe",     "back_x",
                         "back_y",      "back_z",      "neck_x",      "neck_y",   "neck_z",
                         "lshoulder_x", "lshoulder_y", "lshoulder_z", "lelbow_y", "lelbow_z",
                         "rshoulder_x", "rshoulder_y", "rshoulder_z", "relbow_y", "relbow_z"};
  for (int j = 0; j < 30; ++j) {
    INFO(j);
    CHECK(m.dofs[j].name == order[j]);
    const char last = m.dofs[j].name.back();
    const Eigen::Vector3d expect = last == 'x'   ? Eigen::Vector3d::UnitX()
                                   : last == 'z' ? Eigen::Vector3d::UnitZ()
                                                 : Eigen::Vector3d::UnitY();
    CHECK(m.dofs[j].axis == expect);
    CHECK(m.dofs[j].limit.model == limit_model::spring_damper);
    CHECK(m.dofs[j].torque_limit > 0);
    CHECK(m.dofs[j].torque_limit < 1e3);
    CHECK(m.dofs[j].limit.lower <= 0.0);  // q = 0 (standing) is inside every range
    CHECK(m.dofs[j].limit.upper >= 0.0);
  }
  // Joint groups per body, as in the paper: 3-DOF back, neck, shoulders, hips; 2-DOF elbows and
  // ankles; hinge knees and toes.
  CHECK(m.bodies[m.body_index("torso")].num_dofs == 3);
  CHECK(m.bodies[m.body_index("head")].num_dofs == 3);
  CHECK(m.bodies[m.body_index("lupper_arm")].num_dofs == 3);
  CHECK(m.bodies[m.body_index("llower_arm")].num_dofs == 2);
  CHECK(m.bodies[m.body_index("rthigh")].num_dofs == 3);
  CHECK(m.bodies[m.body_index("rshin")].num_dofs == 1);
  CHECK(m.bodies[m.body_index("rfoot")].num_dofs == 2);
  CHECK(m.bodies[m.body_index("rtoes")].num_dofs == 1);
  CHECK(m.bodies[0].name == "pelvis");
}

TEST_CASE("wang2009_humanoid mass, geometry and contacts", "[models][wang2009]") {
  const floating_model m = wang2009_humanoid();
  CHECK(m.total_mass() == Approx(70.0).epsilon(1e-12));
  CHECK(standing_height(m) == Approx(1.65).epsilon(1e-12));
  // Feet flat: all sole and toe points on one plane at q = 0; the toe-top points above it (the
  // body points, role other, are checked in "every body of wang2009_humanoid has contact points").
  const auto o = neutral_body_origins(m);
  const double ground = neutral_lowest_contact(m);
  int soles = 0, toes = 0, tops = 0;
  for (const contact_point& c : m.contact_points) {
    const double z = o[c.body].z() + c.position.z();
    if (c.role == contact_point::kind::other) continue;
    if (c.role == contact_point::kind::toe_top) {
      CHECK(z > ground + 0.01);
      ++tops;
    } else {
      CHECK(z == Approx(ground).margin(1e-12));
      soles += c.role == contact_point::kind::sole;
      toes += c.role == contact_point::kind::toe;
    }
  }
  CHECK(soles == 8);
  CHECK(toes == 8);
  CHECK(tops == 4);
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::sole) == 4);
    CHECK(models_test::count_contacts(m, S + "toes", contact_point::kind::toe) == 4);
    CHECK(models_test::count_contacts(m, S + "toes", contact_point::kind::toe_top) == 2);
    // The four points of each box are its bottom corners.
    const body& foot = m.bodies[m.body_index(S + "foot")];
    REQUIRE(foot.shapes.size() == 1);
    const shape& box = foot.shapes[0];
    CHECK(box.type == shape::kind::box);
    CHECK(models_test::count_contacts(m, S + "foot", contact_point::kind::other) == 0);
    CHECK(models_test::count_contacts(m, S + "toes", contact_point::kind::other) == 0);
    for (const contact_point& c : m.contact_points) {
      if (c.body != m.body_index(S + "foot")) continue;
      const Eigen::Vector3d rel = (c.position - box.center).cwiseAbs();
      CHECK(rel.isApprox(box.half_extents, 1e-12));
      CHECK(c.position.z() < box.center.z());
    }
  }
  const Eigen::VectorXd q = standing_configuration(m);
  CHECK(q[2] == Approx(-ground));
  CHECK(q[3] == 1.0);
  // Whole-body COM at 55-57 % of stature for a standing adult (Winter 2009), above the feet.
  const Eigen::Vector3d c = models_test::neutral_com(m);
  CHECK((c.z() - ground) / 1.65 == Approx(0.56).margin(0.02));
  CHECK(std::abs(c.y()) < 1e-12);
  // The foot + toe COM lies where de Leva's foot COM is (44.15 % of the length from the heel).
  const body& foot = m.bodies[m.body_index("lfoot")];
  const body& toe = m.bodies[m.body_index("ltoes")];
  const double foot_len = foot.length + toe.length;
  const double heel_x = foot.shapes[0].center.x() - foot.shapes[0].half_extents.x();
  const double cx = (foot.mass * foot.com.x() + toe.mass * (toe.joint_offset.x() + toe.com.x())) /
                    (foot.mass + toe.mass);
  CHECK((cx - heel_x) / foot_len == Approx(0.4415).margin(0.005));
  CHECK(foot.mass + toe.mass == Approx(70.0 * 0.0137));
}

namespace {
/// Distance of body-frame point p from the surface of shape s, m.
double distance_to_surface(const shape& s, const Eigen::Vector3d& p) {
  switch (s.type) {
    case shape::kind::box: {
      // On the surface: inside or on the box, and on at least one face.
      const Eigen::Vector3d rel = (p - s.center).cwiseAbs() - s.half_extents;
      return rel.maxCoeff() <= 0 ? -rel.maxCoeff() : rel.cwiseMax(0.0).norm();
    }
    case shape::kind::capsule: {
      const Eigen::Vector3d a = s.p1 - s.p0;
      const double t = std::clamp((p - s.p0).dot(a) / a.squaredNorm(), 0.0, 1.0);
      return std::abs((p - (s.p0 + t * a)).norm() - s.radius);
    }
    case shape::kind::sphere:
      return std::abs((p - s.center).norm() - s.radius);
  }
  return 1e9;
}

/// The body points (role other) of a humanoid30 character: 43, on every body but the feet and
/// toes, each on the surface of one of its body's visual shapes, mirror-symmetric, and at least
/// 0.2 H above the sole plane at q = 0 (the knees' front points are about 0.26 H up, the long-armed
/// character's hand tips 0.24 H), so that standing and walking do not touch the ground with them.
void check_body_points(const floating_model& m) {
  INFO(m.name);
  const auto o = neutral_body_origins(m);
  const double ground = neutral_lowest_contact(m), H = standing_height(m);
  std::vector<int> per_body(m.bodies.size(), 0);
  int others = 0;
  double lowest = 1e9;
  for (const contact_point& c : m.contact_points) {
    ++per_body[c.body];
    if (c.role != contact_point::kind::other) continue;
    INFO(c.name);
    ++others;
    const body& bd = m.bodies[c.body];
    CHECK(bd.name.find("foot") == std::string::npos);
    CHECK(bd.name.find("toes") == std::string::npos);
    double d = 1e9;
    for (const shape& s : bd.shapes) d = std::min(d, distance_to_surface(s, c.position));
    CHECK(d < 1e-12);
    const double z = o[c.body].z() + c.position.z() - ground;
    CHECK(z >= 0.2 * H);
    lowest = std::min(lowest, z);
    // Its mirror image (l <-> r, y negated; central points mirror to a point of the same body).
    std::string mirror = c.name;
    if (c.name[0] == 'l' || c.name[0] == 'r') mirror[0] = c.name[0] == 'l' ? 'r' : 'l';
    if (c.name.find("left") != std::string::npos)
      mirror.replace(c.name.find("left"), 4, "right");
    else if (c.name.find("right") != std::string::npos)
      mirror.replace(c.name.find("right"), 5, "left");
    int found = 0;
    for (const contact_point& e : m.contact_points)
      if (e.name == mirror) {
        ++found;
        CHECK(e.body == m.mirror_body[c.body]);
        CHECK(e.role == contact_point::kind::other);
        CHECK(e.position.isApprox(c.position.cwiseProduct(Eigen::Vector3d(1, -1, 1)), 1e-12));
      }
    CHECK(found == 1);
  }
  CHECK(others == 43);
  CHECK(lowest < 0.3 * H);  // the check above is not vacuous
  // Every body can touch the ground.
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    INFO(m.bodies[b].name);
    CHECK(per_body[b] >= 1);
  }
  // Per body: pelvis 4 bottom corners, torso 8 corners, head 13, thigh 3 (buttock, hip and knee
  // lateral), shin 1 (knee front), upper arm 3 (shoulder lateral, elbow lateral and medial), lower
  // arm 2 (elbow back, hand tip).
  using models_test::count_contacts;
  constexpr auto other = contact_point::kind::other;
  CHECK(count_contacts(m, "pelvis", other) == 4);
  CHECK(count_contacts(m, "torso", other) == 8);
  CHECK(count_contacts(m, "head", other) == 13);
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    CHECK(count_contacts(m, S + "thigh", other) == 3);
    CHECK(count_contacts(m, S + "shin", other) == 1);
    CHECK(count_contacts(m, S + "upper_arm", other) == 3);
    CHECK(count_contacts(m, S + "lower_arm", other) == 2);
  }
  // A few points where their names put them.
  const auto at = [&](const char* name) {
    for (const contact_point& c : m.contact_points)
      if (c.name == name) return Eigen::Vector3d(o[c.body] + c.position);
    FAIL("no contact point " << name);
    return Eigen::Vector3d(0, 0, 0);
  };
  const body& head = m.bodies[m.body_index("head")];
  CHECK(at("head_top").z() == Approx(o[m.body_index("head")].z() + head.segment_end.z()));
  CHECK(at("lknee_front").x() > 0);
  CHECK(at("lknee_front").z() ==
        Approx(o[m.body_index("lshin")].z() - m.bodies[m.body_index("lshin")].shapes[0].radius));
  CHECK(at("lbuttock").x() < 0);
  CHECK(at("torso_back_left_top").x() < 0);
  CHECK(at("torso_back_left_top").y() > 0);
  CHECK(at("torso_back_left_top").z() == Approx(o[m.body_index("head")].z()));
  CHECK(at("lhand_tip").z() < at("lelbow_back").z());
  CHECK(at("lshoulder_lat").y() > at("torso_front_left_top").y());
}
}  // namespace

TEST_CASE("every body of wang2009_humanoid has contact points", "[models][wang2009]") {
  for (const wang2009_shape shape : wang2009_shapes) check_body_points(wang2009_humanoid(shape));
  // The foot and toe points are unchanged: 4 sole, 4 toe and 2 toe-top points per foot, first.
  const floating_model m = wang2009_humanoid();
  REQUIRE(m.contact_points.size() == 20 + 43);
  for (std::size_t k = 0; k < m.contact_points.size(); ++k)
    CHECK((m.contact_points[k].role == contact_point::kind::other) == (k >= 20));
}

TEST_CASE("wang2009_humanoid inertias follow de Leva's radii of gyration", "[models][wang2009]") {
  const floating_model m = wang2009_humanoid(wang2009_body{.height = 1.741, .mass = 73.0});
  // de Leva's reference subject: masses are exactly the table's percentages of 73 kg.
  const body& th = m.bodies[m.body_index("lthigh")];
  CHECK(th.mass == Approx(0.1416 * 73.0));
  CHECK(th.inertia(0, 0) == Approx(th.mass * std::pow(0.329 * th.length, 2)));
  CHECK(th.inertia(2, 2) == Approx(th.mass * std::pow(0.149 * th.length, 2)));
  CHECK(m.bodies[m.body_index("head")].mass == Approx(0.0694 * 73.0));
  CHECK(m.bodies[m.body_index("torso")].mass == Approx((0.1596 + 0.1633) * 73.0));
  CHECK(m.bodies[m.body_index("rlower_arm")].mass == Approx((0.0162 + 0.0061) * 73.0));
  // Lengths: de Leva's scaled so that ankle height (3.9 %) + vertical chain = stature.
  const double s = (1.741 * (1 - 0.039)) / 1.7087;
  CHECK(th.length == Approx(0.4222 * s));
  CHECK(m.bodies[m.body_index("lshin")].length == Approx(0.4403 * s));
  CHECK(m.bodies[m.body_index("head")].length == Approx(0.2429 * s));
  // Welded torso: parallel-axis sum of the middle and upper trunk.
  const body& torso = m.bodies[m.body_index("torso")];
  const double Lm = 0.2155 * s, Lu = 0.2421 * s;
  const double mm = 0.1633 * 73, mu = 0.1596 * 73;
  const double zm = Lm * (1 - 0.4502), zu = Lm + Lu * (1 - 0.5066);
  const double zc = (mm * zm + mu * zu) / (mm + mu);
  CHECK(torso.com.z() == Approx(zc));
  const double Iyy = mm * std::pow(0.383 * Lm, 2) + mm * std::pow(zm - zc, 2) +
                     mu * std::pow(0.320 * Lu, 2) + mu * std::pow(zu - zc, 2);
  CHECK(torso.inertia(1, 1) == Approx(Iyy));
  // Box feet: solid-box inertia.
  const body& ft = m.bodies[m.body_index("rfoot")];
  const Eigen::Vector3d sz = 2 * ft.shapes[0].half_extents;
  CHECK(ft.inertia(1, 1) == Approx(ft.mass * (sz.x() * sz.x() + sz.z() * sz.z()) / 12));
}

TEST_CASE("wang2009_humanoid mirror map and limit stability", "[models][wang2009]") {
  const floating_model m = wang2009_humanoid();
  models_test::check_mirror(m, 12);  // hip 3 + knee + ankle 2 + toe + shoulder 3 + elbow 2
  CHECK(m.mirror_sign[m.dof_index("lhip_x")] == -1.0);
  CHECK(m.mirror_sign[m.dof_index("lhip_y")] == 1.0);
  CHECK(m.mirror_sign[m.dof_index("lhip_z")] == -1.0);
  CHECK(m.mirror_dof[m.dof_index("lankle_x")] == m.dof_index("rankle_x"));
  CHECK(m.mirror_dof[m.dof_index("back_z")] == m.dof_index("back_z"));
  CHECK(m.mirror_sign[m.dof_index("back_z")] == -1.0);
  CHECK(m.mirror_body[m.body_index("ltoes")] == m.body_index("rtoes"));
  models_test::check_limit_stability(m);
}

TEST_CASE("wang2009 presets: Figure 8 heights and masses", "[models][wang2009]") {
  struct expect {
    wang2009_shape shape;
    const char* name;
    double height, mass;
  };
  const expect fig8[] = {{wang2009_shape::long_arm, "long_arm", 1.27, 65},
                         {wang2009_shape::thin, "thin", 1.65, 41},
                         {wang2009_shape::short_, "short", 1.65, 57},
                         {wang2009_shape::stocky, "stocky", 1.65, 70},
                         {wang2009_shape::overweight, "overweight", 1.61, 86},
                         {wang2009_shape::tall, "tall", 1.96, 79}};
  for (const expect& e : fig8) {
    INFO(e.name);
    const wang2009_body b = wang2009_preset(e.shape);
    CHECK(b.name == e.name);
    CHECK(b.height == e.height);
    CHECK(b.mass == e.mass);
    const floating_model m = wang2009_humanoid(e.shape);
    CHECK(m.name == std::string("wang2009_") + e.name);
    CHECK(m.num_joint_dofs() == 30);
    // Stated tolerance: 1e-9 relative (the geometry is constructed to the requested size).
    CHECK(m.total_mass() == Approx(e.mass).epsilon(1e-9));
    CHECK(standing_height(m) == Approx(e.height).epsilon(1e-9));
    models_test::check_limit_stability(m);
    models_test::check_mirror(m, 12);
    CHECK(wang2009_preset(std::string_view(e.name)).height == e.height);
  }
  CHECK(wang2009_preset("long arm").arm_length_scale == 1.5);
  // The long-armed humanoid's arms are longer and heavier; the overweight one's trunk heavier.
  const floating_model la = wang2009_humanoid(wang2009_shape::long_arm);
  const floating_model ref =
      wang2009_humanoid(wang2009_preset(wang2009_shape::stocky).scaled_to(1.27, 65.0));
  const auto arm = [](const floating_model& m) {
    return m.bodies[m.body_index("lupper_arm")].mass + m.bodies[m.body_index("llower_arm")].mass;
  };
  CHECK(arm(la) > 2.0 * arm(ref));
  CHECK(la.bodies[la.body_index("lupper_arm")].length ==
        Approx(1.5 * ref.bodies[ref.body_index("lupper_arm")].length));
  const floating_model ow = wang2009_humanoid(wang2009_shape::overweight);
  const floating_model ow_ref = wang2009_humanoid(wang2009_body{.height = 1.61, .mass = 86});
  CHECK(ow.bodies[0].mass > 1.1 * ow_ref.bodies[0].mass);  // 1.3 before renormalizing to 86 kg
  CHECK_THROWS_WITH(wang2009_preset("giant"), Contains("giant"));
}

TEST_CASE("wang2009_humanoid scales with height and mass", "[models][wang2009]") {
  const floating_model a = wang2009_humanoid(wang2009_body{.name = "a", .height = 1.8, .mass = 80});
  CHECK(a.total_mass() == Approx(80.0).epsilon(1e-12));
  CHECK(standing_height(a) == Approx(1.8).epsilon(1e-12));
  // Same proportions: every length scales by the height ratio, every mass by the mass ratio.
  const floating_model b = wang2009_humanoid(wang2009_body{.name = "b", .height = 0.9, .mass = 20});
  for (int i = 0; i < a.num_bodies(); ++i) {
    INFO(a.bodies[i].name);
    CHECK(b.bodies[i].mass == Approx(a.bodies[i].mass / 4.0));
    CHECK(b.bodies[i].joint_offset.isApprox(a.bodies[i].joint_offset / 2.0, 1e-12));
    CHECK(b.bodies[i].inertia.isApprox(a.bodies[i].inertia / 16.0, 1e-12));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(wang2009_humanoid(wang2009_body{.height = -1.0}),
                    Contains("height") && Contains("-1"));
  CHECK_THROWS_WITH(wang2009_humanoid(wang2009_body{.mass = 0.0}),
                    Contains("mass") && Contains("got 0"));
  CHECK_THROWS_WITH(wang2009_humanoid(wang2009_body{.height = nan}),
                    Contains("height") && Contains("nan"));
  CHECK_THROWS_WITH(wang2009_humanoid(wang2009_body{.mass = nan}),
                    Contains("mass") && Contains("nan"));
  CHECK_THROWS_WITH(
      wang2009_humanoid(wang2009_body{.arm_length_scale = std::numeric_limits<double>::infinity()}),
      Contains("arm_length_scale"));
}
