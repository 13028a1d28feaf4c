// Unit tests of the nearest-neighbor controller (controllers/nearest_neighbor.hpp): eq. 1 against a
// brute-force search, left/right symmetric nodes, the activation order restriction, initialization
// along the target motion (mu_i = zeta_{i+1}), the PD / torso-servo output in both output modes.
#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/controllers/nearest_neighbor.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "support/sharon2005.hpp"

using namespace gaitsynth;
using sharon_test::small_biped;
using sharon_test::small_walk;
using sharon_test::vec;
using NN = nearest_neighbor_controller<planar_root>;

namespace {
// The small biped has no feet: the stance leg comes from the nodes' labels.
nearest_neighbor_options labels_only(nearest_neighbor_options o = {}) {
  o.stance_from_contacts = false;
  return o;
}
}  // namespace

TEST_CASE("nearest neighbor: initialization along the target motion", "[controllers][nn]") {
  const auto m = small_biped();
  const auto walk = small_walk(m);
  nearest_neighbor_options o;
  o.num_nodes = 12;
  const NN c(m, walk, labels_only(o));
  REQUIRE(c.num_inputs() == 5);  // root_pitch + 4 joints
  CHECK(c.num_free_nodes() == 6);
  CHECK(c.num_parameters() == 6 * (4 + 4));
  Eigen::VectorXd q(m.nq()), qn(m.nq());
  const double P = walk.period();  // 1.2 s
  for (int i = 0; i < 12; ++i) {
    walk.pose(P * i / 12, q);
    walk.pose(P * (i + 1) / 12, qn);
    const nn_node nd = c.node(i);
    // zeta_i on the trajectory (mirrored nodes too: the walk is symmetric)...
    CHECK(nd.location[0] == Approx(q[2]).margin(1e-12));
    CHECK((nd.location.tail(4) - q.tail(4)).norm() < 1e-12);
    // ...and mu_i = zeta_{i+1}: each node drives toward the next node's location.
    CHECK((nd.output - c.node((i + 1) % 12).location.tail(4)).norm() < 1e-12);
    CHECK((nd.output - qn.tail(4)).norm() < 1e-12);
    CHECK(nd.torso_pitch == Approx(qn[2]).margin(1e-12));
    CHECK(nd.stance == (i < 6 ? stance_side::right : stance_side::left));
  }
}

TEST_CASE("nearest neighbor: eq. 1 selection equals a brute-force weighted search",
          "[controllers][nn]") {
  const auto m = small_biped();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  nearest_neighbor_options o;
  o.num_nodes = 10;
  o.symmetric = false;
  o.input_weights = {2.0, 1.0, 0.5, 1.0, 0.0};  // the last input (rknee) is ignored
  std::vector<nn_node> nodes(10);
  for (auto& n : nodes) {
    n.location = Eigen::VectorXd::NullaryExpr(5, [&] { return U(rng); });
    n.output = Eigen::VectorXd::NullaryExpr(4, [&] { return U(rng); });
  }
  const NN c(m, labels_only(o), nodes);
  const Eigen::VectorXd w = vec({2.0, 1.0, 0.5, 1.0, 0.0});
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd q = Eigen::VectorXd::NullaryExpr(m.nq(), [&] { return U(rng); });
    Eigen::VectorXd zeta(5);
    zeta << q[2], q.tail(4);
    int best = -1;
    double bd = 1e300;
    for (int i = 0; i < 10; ++i) {
      const double d = (w.array() * (zeta - nodes[i].location).array()).matrix().norm();
      if (d < bd) bd = d, best = i;
    }
    CHECK(c.nearest(q) == best);
    // The weight-0 coordinate does not matter.
    q[6] += 10.0;
    CHECK(c.nearest(q) == best);
  }
}

TEST_CASE("nearest neighbor: symmetric nodes, only half are free", "[controllers][nn]") {
  const auto m = small_biped();
  const NN c0(m, small_walk(m), labels_only());
  NN c = c0;
  std::vector<double> p = c.parameters();
  REQUIRE(p.size() == 48);
  const auto names = c.parameter_names();
  CHECK(names[0] == "node0.location.lhip");
  CHECK(names[4] == "node0.output.lhip");
  CHECK(names[8] == "node1.location.lhip");
  for (std::size_t i = 0; i < p.size(); ++i) p[i] += 0.01 * static_cast<double>(i);
  c.bind(p);
  CHECK(c.parameters() == p);
  for (int i = 0; i < 6; ++i) {
    const nn_node a = c.node(i), b = c.node(i + 6);
    // Location: pitch kept, left and right legs swapped (mirror signs are +1 for pitch joints).
    CHECK(b.location[0] == a.location[0]);
    CHECK(b.location[1] == a.location[3]);  // lhip <- rhip
    CHECK(b.location[2] == a.location[4]);
    CHECK(b.location[3] == a.location[1]);
    CHECK(b.location[4] == a.location[2]);
    CHECK(b.output[0] == a.output[2]);
    CHECK(b.output[1] == a.output[3]);
    CHECK(b.output[2] == a.output[0]);
    CHECK(b.output[3] == a.output[1]);
    CHECK(b.stance == opposite(a.stance));
  }
  // The mirrored pose selects the mirrored node.
  Eigen::VectorXd q(m.nq()), mq(m.nq());
  for (int i = 0; i < 6; ++i) {
    q.setZero();
    q[2] = c.node(i).location[0];
    q.tail(4) = c.node(i).location.tail(4);
    mirror_configuration(m, q, mq);
    CHECK(c.nearest(q) == i);
    CHECK(c.nearest(mq) == i + 6);
  }
  CHECK_THROWS_WITH(c.bind(std::vector<double>(47, 0.0)), Catch::Contains("expected 48, got 47"));
  std::vector<double> bad = p;
  bad[5] = std::nan("");
  CHECK_THROWS_WITH(c.bind(bad), Catch::Contains("parameter 5 is not finite"));
}

TEST_CASE("nearest neighbor: restricted activation order", "[controllers][nn]") {
  const auto m = small_biped();
  nearest_neighbor_options o;
  o.max_advance = 1;
  NN c(m, small_walk(m), labels_only(o));
  sharon_test::sensor_fixture<planar_root> f(m);
  NN::state_type st = c.make_state(m);
  Eigen::VectorXd cmd(4);
  auto put_at = [&](int node) {
    f.q.setZero();
    f.q[2] = c.node(node).location[0];
    f.q.tail(4) = c.node(node).location.tail(4);
  };
  put_at(3);
  c.command(f.update(), st, cmd);
  CHECK(st.active == 3);  // first command: unrestricted search
  put_at(7);              // nearest is node 7, but from 3 only 3 or 4 may activate
  c.command(f.update(), st, cmd);
  CHECK(st.active == 4);
  c.command(f.update(), st, cmd);
  CHECK(st.active == 5);
  put_at(2);  // going backwards is not allowed: stays (node 5 or 6 is the nearer of the two)
  c.command(f.update(), st, cmd);
  CHECK((st.active == 5 || st.active == 6));
  // Unrestricted controller jumps directly.
  NN u(m, small_walk(m), labels_only());
  NN::state_type su = u.make_state(m);
  put_at(3);
  u.command(f.update(), su, cmd);
  put_at(7);
  u.command(f.update(), su, cmd);
  CHECK(su.active == 7);
  CHECK(su.switches == 1);
  // Wrap-around: from the last node, node 0 may follow.
  put_at(11);
  NN::state_type s2 = c.make_state(m);
  c.command(f.update(), s2, cmd);
  put_at(0);
  c.command(f.update(), s2, cmd);
  CHECK(s2.active == 0);
}

TEST_CASE("nearest neighbor: PD servos, torso servo on the stance hip, torque limit",
          "[controllers][nn]") {
  const auto m = small_biped();
  nearest_neighbor_options o;
  o.default_kp = 500;
  o.default_kd = 50;
  o.torso_kp = 1000;
  o.torso_kd = 100;
  o.compensate_swing_hip = false;
  o = labels_only(o);
  const NN c(m, small_walk(m), o);
  sharon_test::sensor_fixture<planar_root> f(m);
  f.q.setZero();
  f.q[2] = c.node(2).location[0];
  f.q.tail(4) = c.node(2).location.tail(4);
  f.q[3] += 0.01;
  f.v << 0.1, -0.2, 0.3, 0.4, -0.5, 0.6, -0.7;
  NN::state_type st = c.make_state(m);
  Eigen::VectorXd tau(4);
  c.command(f.update(), st, tau);
  REQUIRE(st.active == 2);
  const nn_node nd = c.node(2);
  REQUIRE(nd.stance == stance_side::right);  // node 2 governs the listed (right stance) step
  // Swing (left) hip and both knees: PD to the node's output.
  for (int j : {0, 1, 3})
    CHECK(tau[j] == Approx(500 * (nd.output[j] - f.q[3 + j]) - 50 * f.v[3 + j]));
  // Stance (right) hip: minus the torso PD torque (the hip torque reacts on the torso).
  const double torso = 1000 * (nd.torso_pitch - f.q[2]) - 100 * f.v[2];
  CHECK(tau[2] == Approx(-torso));

  // With the swing hip compensated, the torso feels exactly the servo torque: the stance and swing
  // hip torques (both reacting on the torso) sum to minus the torso PD torque.
  nearest_neighbor_options oc = o;
  oc.compensate_swing_hip = true;
  const NN cc(m, small_walk(m), oc);
  NN::state_type stc = cc.make_state(m);
  Eigen::VectorXd tauc(4);
  cc.command(f.s, stc, tauc);
  CHECK(tauc[0] == Approx(tau[0]));
  CHECK(tauc[2] + tauc[0] == Approx(-torso));

  // joint_target mode with a pd_actuator of the same gains produces the same torques.
  nearest_neighbor_options ot = o;
  ot.output = command_kind::joint_target;
  const NN ct(m, small_walk(m), ot);
  NN::state_type st2 = ct.make_state(m);
  Eigen::VectorXd target(4), tau2(4);
  ct.command(f.s, st2, target);
  const pd_actuator pd = pd_actuator::uniform(m, 500, 50);
  auto ast = pd.make_state(m);
  const sim_state ss{f.q, f.v, 0.0};
  pd.torques(m, ss, target, ast, tau2);
  CHECK((tau2 - tau).norm() < 1e-9 * (1 + tau.norm()));

  // Torque limit clamps every servo.
  f.q[4] += 3.0;  // a large knee error
  nearest_neighbor_options ol = o;
  ol.torque_limit = 370;
  const NN cl(m, small_walk(m), ol);
  NN::state_type st3 = cl.make_state(m);
  cl.command(f.update(), st3, tau);
  CHECK(std::abs(tau[1]) == Approx(370));
}

TEST_CASE("nearest neighbor: bad options are named", "[controllers][nn]") {
  const auto m = small_biped();
  const auto w = small_walk(m);
  nearest_neighbor_options o;
  o.num_nodes = 7;
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("even num_nodes, got 7"));
  o = labels_only();
  o.input = {"root_pitch", "lhip", "lknee"};
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("'lhip' has no mirror image"));
  o = labels_only();
  o.input = {"root_pitch", "lhipp"};
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("unknown input coordinate 'lhipp'"));
  o = labels_only();
  o.free_dofs = {"lhip", "neck"};
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("unknown free DOF 'neck'"));
  o = labels_only();
  o.input_weights = {1, 1};
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("input_weights"));
  o = labels_only();
  o.left_hip = "lknee_x";
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("no joint DOF named 'lknee_x'"));
  o = labels_only();
  o.max_advance = 12;
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("max_advance must be < num_nodes"));
  o = {};  // stance from contacts needs the feet
  o.stance_from_contacts = true;
  CHECK_THROWS_WITH(NN(m, w, o), Catch::Contains("no body named 'lfoot'"));
}

TEST_CASE("nearest neighbor: JSON round trip is exact", "[controllers][nn][json]") {
  const auto m = small_biped();
  nearest_neighbor_options o;
  o.max_advance = 2;
  o.kp = {100, 200, 300, 400};
  o.compensate_swing_hip = false;
  NN c(m, small_walk(m), labels_only(o));
  std::vector<double> p = c.parameters();
  for (std::size_t i = 0; i < p.size(); ++i) p[i] += std::sin(1.0 + static_cast<double>(i)) / 3;
  c.bind(p);
  const std::string text = nearest_neighbor_to_json(m, c, {{"evaluations", 12}}).dump(1);
  const NN back = nearest_neighbor_from_json(m, nlohmann::json::parse(text), "c.json");
  CHECK(back.parameters() == p);
  CHECK(back.opts().max_advance == 2);
  CHECK(back.kp()[3] == 400);
  CHECK(!back.opts().compensate_swing_hip);
  CHECK(!back.opts().stance_from_contacts);
  for (int i = 0; i < 12; ++i) {
    CHECK(back.node(i).location == c.node(i).location);
    CHECK(back.node(i).output == c.node(i).output);
    CHECK(back.node(i).torso_pitch == c.node(i).torso_pitch);
    CHECK(back.node(i).stance == c.node(i).stance);
  }
  auto j = nlohmann::json::parse(text);
  j["nodes"][1]["output"]["lhipp"] = 0.1;
  CHECK_THROWS_WITH(nearest_neighbor_from_json(m, j, "c.json"),
                    Catch::Contains("c.json: nodes[1].output.lhipp: unknown DOF name 'lhipp'"));
  j = nlohmann::json::parse(text);
  j["nodes"][2]["location"].erase("rknee");
  CHECK_THROWS_WITH(nearest_neighbor_from_json(m, j, "c.json"),
                    Catch::Contains("c.json: nodes[2].location.rknee: missing"));
}
