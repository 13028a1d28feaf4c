// Unit tests of the cyclic keyframe target motion (motion/keyframes.hpp) and of its JSON form
// (motion/keyframes_json.hpp): interpolation, periodic continuation with mirroring and advance, the
// initial state, and the error messages for malformed / inconsistent files.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/motion/keyframes.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"

using namespace gaitsynth;

namespace {

// A small planar biped built here (independent of the library's characters): torso root with two
// legs of thigh + shin; DOFs lhip, lknee, rhip, rknee (q = [x, z, pitch, lhip, lknee, rhip,
// rknee]).
planar_model small_biped() {
  model_builder<planar_root> b("small_biped");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal();
  b.add_body({.name = "torso", .mass = 10, .inertia = I});
  for (std::string s : {"l", "r"}) {
    b.add_body({.name = s + "thigh",
                .parent = "torso",
                .mass = 2,
                .com = {0, 0, -0.2},
                .inertia = I,
                .dofs = {{.name = s + "hip"}}});
    b.add_body({.name = s + "shin",
                .parent = s + "thigh",
                .joint_offset = {0, 0, -0.4},
                .mass = 1,
                .com = {0, 0, -0.2},
                .inertia = I,
                .dofs = {{.name = s + "knee"}}});
  }
  return b.build();
}

Eigen::VectorXd vec(std::initializer_list<double> x) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(x.size()));
  Eigen::Index i = 0;
  for (double e : x) v[i++] = e;
  return v;
}

keyframe_motion<planar_root> two_key_walk(const planar_model& m) {
  // Listed step: right stance. Keyframe 0 at t=0, keyframe 1 at t=0.2, wraps (mirrored) at 0.5 s.
  std::vector<keyframe> k = {{0.0, vec({0.0, 1.0, 0.1, 0.3, 0.0, -0.2, 0.1})},
                             {0.2, vec({0.2, 1.1, 0.0, 0.0, 0.8, 0.1, 0.0})}};
  return keyframe_motion<planar_root>(m, k, 0.5, true, vec({0.6, 0.0, 0.0}), stance_side::right);
}

}  // namespace

TEST_CASE("keyframe motion interpolates linearly between keyframes", "[motion][keyframes]") {
  const auto m = small_biped();
  const auto mo = two_key_walk(m);
  Eigen::VectorXd q(m.nq());
  mo.pose(0.0, q);
  CHECK((q - mo.keyframes()[0].q).norm() < 1e-15);
  mo.pose(0.2, q);
  CHECK((q - mo.keyframes()[1].q).norm() < 1e-15);
  mo.pose(0.05, q);  // a quarter of the way from keyframe 0 to keyframe 1
  const Eigen::VectorXd expect = 0.75 * mo.keyframes()[0].q + 0.25 * mo.keyframes()[1].q;
  CHECK((q - expect).norm() < 1e-14);
  CHECK(mo.period() == Approx(1.0));
  CHECK(mo.speed() == Approx(1.2));
}

TEST_CASE("keyframe motion mirrors odd steps and advances the root", "[motion][keyframes]") {
  const auto m = small_biped();
  const auto mo = two_key_walk(m);
  Eigen::VectorXd q(m.nq());
  // At the wrap time 0.5 s the pose is keyframe 0 mirrored (lhip <-> rhip, lknee <-> rknee) and
  // advanced by 0.6 m.
  mo.pose(0.5, q);
  const Eigen::VectorXd k0 = mo.keyframes()[0].q;
  CHECK(q[0] == Approx(0.6));
  CHECK(q[1] == Approx(k0[1]));
  CHECK(q[2] == Approx(k0[2]));
  CHECK(q[3] == Approx(k0[5]));
  CHECK(q[4] == Approx(k0[6]));
  CHECK(q[5] == Approx(k0[3]));
  CHECK(q[6] == Approx(k0[4]));
  // Just before the wrap, the pose approaches that mirrored keyframe continuously.
  Eigen::VectorXd q2(m.nq());
  mo.pose(0.5 - 1e-9, q2);
  CHECK((q - q2).norm() < 1e-6);
  // One full cycle (1 s) later: same pose, root 1.2 m further.
  mo.pose(0.13, q);
  mo.pose(1.13, q2);
  CHECK(q2[0] - q[0] == Approx(1.2));
  CHECK((q2.tail(m.nq() - 1) - q.tail(m.nq() - 1)).norm() < 1e-12);
  // Negative times continue the motion backwards.
  mo.pose(-0.87, q2);
  CHECK(q[0] - q2[0] == Approx(1.2));
  CHECK(mo.stance_at(0.1) == stance_side::right);
  CHECK(mo.stance_at(0.6) == stance_side::left);
  CHECK(mo.stance_at(1.1) == stance_side::right);
  CHECK(mo.cycle_keyframes().size() == 4);
}

TEST_CASE("keyframe velocity is the slope of the interpolation, and the initial state",
          "[motion][keyframes]") {
  const auto m = small_biped();
  const auto mo = two_key_walk(m);
  Eigen::VectorXd v(m.nv()), qa(m.nq()), qb(m.nq());
  for (double t : {0.0, 0.1, 0.3, 0.47, 0.61, 0.9, 1.75}) {
    mo.velocity(t, v);
    const double h = 1e-6;
    mo.pose(t + h, qb);
    mo.pose(t + 2 * h, qa);
    const Eigen::VectorXd fd = (qa - qb) / h;  // forward difference inside the same segment
    CHECK((v - fd).norm() < 1e-6 * (1 + v.norm()));
  }
  const sim_state s = mo.initial_state();
  CHECK((s.q - mo.keyframes()[0].q).norm() < 1e-15);
  const Eigen::VectorXd slope = (mo.keyframes()[1].q - mo.keyframes()[0].q) / 0.2;
  CHECK((s.v - slope).norm() < 1e-12);
  CHECK(s.t == 0.0);
}

TEST_CASE("keyframe motion rejects bad keyframes", "[motion][keyframes]") {
  const auto m = small_biped();
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq());
  using KM = keyframe_motion<planar_root>;
  CHECK_THROWS_WITH(KM(m, {{0.0, Eigen::VectorXd::Zero(5)}}, 1.0, true),
                    Catch::Contains("keyframe 0 has 5 coordinates") && Catch::Contains("nq = 7"));
  CHECK_THROWS_WITH(KM(m, {{0.0, q}, {0.25, q}, {0.25, q}}, 1.0, true),
                    Catch::Contains("keyframe 2 at 0.25"));
  CHECK_THROWS_WITH(KM(m, {{0.1, q}}, 1.0, true), Catch::Contains("time 0, got 0.1"));
  CHECK_THROWS_WITH(KM(m, {{0.0, q}, {0.5, q}}, 0.5, true), Catch::Contains("end_time"));
  CHECK_THROWS_WITH(KM(m, {{0.0, q}}, 1.0, true, vec({0, 0, 0.25})),
                    Catch::Contains("root_pitch must be 0, got 0.25"));
}

TEST_CASE("mirror_configuration of a floating root flips y and the lateral quaternion parts",
          "[motion][keyframes]") {
  model_builder<floating_root> b("tiny3d");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal();
  b.add_body({.name = "pelvis", .mass = 10, .inertia = I});
  b.add_body({.name = "lleg",
              .parent = "pelvis",
              .mass = 2,
              .inertia = I,
              .dofs = {{.name = "lhip_x", .axis = {1, 0, 0}}, {.name = "lhip_y"}}});
  b.add_body({.name = "rleg",
              .parent = "pelvis",
              .mass = 2,
              .inertia = I,
              .dofs = {{.name = "rhip_x", .axis = {1, 0, 0}}, {.name = "rhip_y"}}});
  const auto m = b.build();
  Eigen::VectorXd q(m.nq()), out(m.nq()), back(m.nq());
  q << 1, 2, 3, 0.9, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7;
  mirror_configuration(m, q, out);
  CHECK(out[1] == -2);
  CHECK(out[4] == Approx(-0.1));
  CHECK(out[5] == Approx(0.2));
  CHECK(out[6] == Approx(-0.3));
  CHECK(out[7] == Approx(-0.6));  // lhip_x <- -rhip_x (roll flips)
  CHECK(out[8] == Approx(0.7));   // lhip_y <- rhip_y (pitch keeps its sign)
  mirror_configuration(m, out, back);
  CHECK((back - q).norm() < 1e-15);  // mirroring twice is the identity
}

// ---- JSON ---------------------------------------------------------------------------------------

namespace {
const char* good_json = R"({
  "format": "gaitsynth.keyframes/1",
  "model": "small_biped",
  "units": "degrees",
  "symmetric": true,
  "stance": "right",
  "end_time": 0.5,
  "advance": {"root_x": 0.6},
  "defaults": {"root_pitch": 0},
  "keyframes": [
    {"time": 0.0, "pose": {"root_x": 0, "root_z": 1.0, "lhip": 20, "lknee": 0, "rhip": -10, "rknee": 5}},
    {"time": 0.2, "pose": [0.2, 1.1, 0, 0, 45, 10, 0]}
  ]
})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  REQUIRE(p != std::string::npos);
  return s.replace(p, from.size(), to);
}
}  // namespace

TEST_CASE("keyframes JSON: reads names, degrees, defaults and arrays",
          "[motion][keyframes][json]") {
  const auto m = small_biped();
  const auto mo = parse_keyframes(m, good_json, "walk.json");
  REQUIRE(mo.num_keyframes() == 2);
  const double d = std::numbers::pi / 180;
  CHECK(mo.keyframes()[0].q[1] == 1.0);
  CHECK(mo.keyframes()[0].q[2] == 0.0);  // from defaults
  CHECK(mo.keyframes()[0].q[3] == Approx(20 * d));
  CHECK(mo.keyframes()[0].q[5] == Approx(-10 * d));
  CHECK(mo.keyframes()[1].q[0] == 0.2);  // translations stay in metres
  CHECK(mo.keyframes()[1].q[4] == Approx(45 * d));
  CHECK(mo.end_time() == 0.5);
  CHECK(mo.symmetric());
  CHECK(mo.stance() == stance_side::right);
  CHECK(mo.advance()[0] == 0.6);
  // Round trip through the writer.
  const auto back = parse_keyframes(m, keyframes_to_json(m, mo).dump(2), "roundtrip");
  for (int k = 0; k < 2; ++k) CHECK((back.keyframes()[k].q - mo.keyframes()[k].q).norm() < 1e-12);
  CHECK(back.advance()[0] == 0.6);
}

TEST_CASE("keyframes JSON: clear errors naming the value and its location",
          "[motion][keyframes][json]") {
  const auto m = small_biped();
  const std::string g = good_json;
  auto err = [&](const std::string& text) {
    try {
      parse_keyframes(m, text, "walk.json");
    } catch (const keyframes_error& e) {
      return std::string(e.what());
    }
    FAIL("no keyframes_error thrown");
    return std::string();
  };
  // Wrong DOF count in an array pose.
  CHECK_THAT(err(replace(g, "[0.2, 1.1, 0, 0, 45, 10, 0]", "[0.2, 1.1, 0, 0, 45, 10]")),
             Catch::StartsWith("walk.json: keyframes[1].pose: wrong DOF count") &&
                 Catch::Contains("nq = 7") && Catch::Contains("got 6"));
  // Non-increasing times.
  CHECK_THAT(err(replace(g, "\"time\": 0.2", "\"time\": 0.0")),
             Catch::StartsWith("walk.json: keyframes[1].time: times must increase") &&
                 Catch::Contains("keyframes[0].time = 0"));
  // Unknown DOF name, listing the known ones.
  CHECK_THAT(err(replace(g, "\"lknee\": 0", "\"lkne\": 0")),
             Catch::StartsWith("walk.json: keyframes[0].pose.lkne: unknown DOF name 'lkne'") &&
                 Catch::Contains("lknee"));
  // Missing DOF without default.
  CHECK_THAT(err(replace(g, "\"lknee\": 0, ", "")),
             Catch::Contains("keyframes[0].pose: missing DOF 'lknee'"));
  // Wrong type.
  CHECK_THAT(err(replace(g, "\"rhip\": -10", "\"rhip\": \"-10\"")),
             Catch::Contains("keyframes[0].pose.rhip: expected a number, got \"-10\""));
  // Model mismatch, units, end_time, first time, malformed JSON, unknown key, advance of an angle.
  CHECK_THAT(err(replace(g, "\"small_biped\"", "\"other\"")),
             Catch::Contains("model: file is for model 'other'"));
  CHECK_THAT(err(replace(g, "\"degrees\"", "\"grads\"")), Catch::Contains("units: expected"));
  CHECK_THAT(err(replace(g, "\"end_time\": 0.5", "\"end_time\": 0.2")),
             Catch::Contains("end_time: must be after the last keyframe's time 0.2"));
  CHECK_THAT(err(replace(g, "\"time\": 0.0", "\"time\": 0.1")),
             Catch::Contains("keyframes[0].time: the first keyframe must be at time 0"));
  CHECK_THAT(err(replace(g, "\"keyframes\": [", "\"keyframes\": [[")),
             Catch::StartsWith("walk.json: malformed JSON"));
  CHECK_THAT(err(replace(g, "\"symmetric\"", "\"symetric\"")),
             Catch::Contains("unknown key 'symetric'"));
  CHECK_THAT(err(replace(g, "{\"root_x\": 0.6}", "{\"lhip\": 0.6}")),
             Catch::Contains("advance.lhip: only the root's translation can advance"));
  CHECK_THROWS_AS(load_keyframes(m, "/nonexistent/walk.json"), keyframes_error);
}
