// The MJCF exporter's text, checked without MuJoCo (tests/io/mjcf.mujoco.cpp loads it in MuJoCo):
// the document is well-formed XML (read by tinyxml2 through viz/xml_check.hpp: balanced tags,
// quoted attributes, only predefined entities; here also no text content and whitespace between
// attributes), it holds exactly one element per model part, numbers read back bit-identical,
// bodies come depth-first with the model's parents, offsets, inertias and hinge axes, the q/v
// permutation maps agree with the file, options do what they say, and bad names or options throw
// std::invalid_argument naming the problem.
#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <locale>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/io/mjcf.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/models/models.hpp"
#include "io/mjcf_test_models.hpp"
#include "viz/xml_check.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

namespace {

// ---- The document as tinyxml2 reads it (viz/xml_check.hpp), copied into a plain tree ---------
struct xml_element {
  std::string name;
  std::map<std::string, std::string> attr;
  std::vector<xml_element> children;
  const std::string& at(const std::string& k) const {
    auto it = attr.find(k);
    if (it == attr.end()) throw std::runtime_error("<" + name + "> has no attribute " + k);
    return it->second;
  }
  bool has(const std::string& k) const { return attr.count(k) > 0; }
};

xml_element copy_element(const tinyxml2::XMLElement& e) {
  xml_element out;
  out.name = e.Name();
  for (const auto* a = e.FirstAttribute(); a; a = a->Next())
    out.attr.emplace(a->Name(), a->Value());
  for (const auto* c = e.FirstChild(); c; c = c->NextSibling()) {
    if (const auto* ce = c->ToElement()) {
      out.children.push_back(copy_element(*ce));
    } else if (const auto* t = c->ToText()) {  // MJCF holds no text, only whitespace
      for (char ch : std::string(t->Value()))
        if (!std::isspace(static_cast<unsigned char>(ch)))
          throw std::runtime_error("text content in <" + out.name + "> (line " +
                                   std::to_string(t->GetLineNum()) + ")");
    }
  }
  return out;
}

// tinyxml2 accepts attributes with no whitespace between them (<a b="1"c="2"/>). MJCF holds no text
// and its values no raw quotes, so outside comments every quoted string after '=' is an attribute
// value, and whitespace, '/', '>' or '?' must follow it.
void check_attribute_separation(const std::string& text) {
  std::size_t p = 0;
  while ((p = text.find_first_of("=<", p)) != std::string::npos) {
    if (text.compare(p, 4, "<!--") == 0) {
      p = text.find("-->", p);
      continue;
    }
    std::size_t q = p + 1;
    while (q < text.size() && std::isspace(static_cast<unsigned char>(text[q]))) ++q;
    if (text[p] == '<' || q >= text.size() || (text[q] != '"' && text[q] != '\'')) {
      p = q;
      continue;
    }
    const std::size_t e = text.find(text[q], q + 1);
    if (e == std::string::npos) return;  // tinyxml2 has refused the document
    if (e + 1 < text.size() && !std::isspace(static_cast<unsigned char>(text[e + 1])) &&
        std::string_view("/>?").find(text[e + 1]) == std::string_view::npos)
      throw std::runtime_error("no whitespace after the attribute value " +
                               text.substr(q, e + 1 - q));
    p = e + 1;
  }
}

xml_element parse(const std::string& s) {
  const viz_test::xml_document doc = viz_test::parse_xml(s);
  xml_element root = copy_element(*doc->RootElement());
  check_attribute_separation(s);
  return root;
}

void collect(const xml_element& e, const std::string& name, std::vector<const xml_element*>& out) {
  if (e.name == name) out.push_back(&e);
  for (const auto& c : e.children) collect(c, name, out);
}
std::vector<const xml_element*> all(const xml_element& e, const std::string& name) {
  std::vector<const xml_element*> out;
  collect(e, name, out);
  return out;
}
std::vector<const xml_element*> kids(const xml_element& e, const std::string& name) {
  std::vector<const xml_element*> out;
  for (const auto& c : e.children)
    if (c.name == name) out.push_back(&c);
  return out;
}

std::vector<double> numbers(const std::string& s) {
  std::istringstream is(s);
  is.imbue(std::locale::classic());
  std::vector<double> out;
  std::string tok;
  while (is >> tok) out.push_back(std::strtod(tok.c_str(), nullptr));
  return out;
}
Eigen::Vector3d vec3_of(const std::string& s) {
  const auto n = numbers(s);
  REQUIRE(n.size() == 3);
  return {n[0], n[1], n[2]};
}

// Pre-order walk of <body> elements.
void bodies_preorder(const xml_element& e, const xml_element* parent,
                     std::vector<std::pair<const xml_element*, const xml_element*>>& out) {
  for (const auto& c : e.children)
    if (c.name == "body") {
      out.emplace_back(&c, parent);
      bodies_preorder(c, &c, out);
    }
}

// Structural checks shared by every model: one element per part, exact numbers, depth-first tree.
template <root_joint Root>
void check_structure(const model<Root>& m, const mjcf_options& opt) {
  const std::string text = to_mjcf_string(m, opt);
  xml_element doc;
  REQUIRE_NOTHROW(doc = parse(text));
  REQUIRE(doc.name == "mujoco");
  CHECK(kids(doc, "compiler").size() == 1);
  CHECK(kids(doc, "compiler")[0]->at("angle") == "radian");
  CHECK(kids(doc, "compiler")[0]->at("inertiafromgeom") == "false");
  const auto& option = *kids(doc, "option").at(0);
  CHECK(std::strtod(option.at("timestep").c_str(), nullptr) == opt.timestep);  // bit-exact
  CHECK(vec3_of(option.at("gravity")) == m.gravity);
  const auto& world = *kids(doc, "worldbody").at(0);

  std::vector<std::pair<const xml_element*, const xml_element*>> bodies;
  bodies_preorder(world, nullptr, bodies);
  REQUIRE(static_cast<int>(bodies.size()) == m.num_bodies());
  CHECK(all(doc, "body").size() == bodies.size());
  CHECK(all(doc, "inertial").size() == bodies.size());
  const std::vector<int> order = mjcf_body_order(m);
  REQUIRE(order.size() == bodies.size());

  std::size_t visual_shapes = 0, n_joints = 0;
  std::vector<int> dof_order_in_file;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const body& bd = m.bodies[order[k]];
    const xml_element& e = *bodies[k].first;
    INFO("body " << bd.name);
    CHECK(e.at("name") == bd.name);
    // Parent in the file is the model's parent; the offset and inertia read back exactly.
    CHECK(vec3_of(e.at("pos")) == bd.joint_offset);
    if (bd.parent < 0) {
      CHECK(bodies[k].second == nullptr);
    } else {
      REQUIRE(bodies[k].second != nullptr);
      CHECK(bodies[k].second->at("name") == m.bodies[bd.parent].name);
    }
    const auto in = kids(e, "inertial");
    REQUIRE(in.size() == 1);
    CHECK(std::strtod(in[0]->at("mass").c_str(), nullptr) == bd.mass);
    CHECK(vec3_of(in[0]->at("pos")) == bd.com);
    // Principal moments and axes reproduce the inertia tensor to rounding; diagonal stays exact.
    const Eigen::Matrix3d& I = bd.inertia;
    const Eigen::Vector3d moments = vec3_of(in[0]->at("diaginertia"));
    const bool diagonal = I(0, 1) == 0 && I(0, 2) == 0 && I(1, 2) == 0;
    CHECK(in[0]->has("quat") == !diagonal);
    if (diagonal) {
      CHECK(moments == I.diagonal());
    } else {
      const auto qv = numbers(in[0]->at("quat"));
      REQUIRE(qv.size() == 4);
      const Eigen::Quaterniond iq(qv[0], qv[1], qv[2], qv[3]);
      CHECK(std::abs(iq.norm() - 1.0) <= 1e-15);
      const Eigen::Matrix3d R = iq.normalized().toRotationMatrix();
      const Eigen::Matrix3d back = R * moments.asDiagonal() * R.transpose();
      CHECK((back - I).cwiseAbs().maxCoeff() <= 1e-14 * I.cwiseAbs().maxCoeff());
    }
    CHECK(moments.minCoeff() > 0);
    // Hinges in DOF order, axes exact, ranges when limited.
    const auto js = kids(e, "joint");
    std::size_t k0 = 0;
    if (bd.parent < 0) {
      if constexpr (Root::nv == 3) {
        REQUIRE(js.size() == 3 + static_cast<std::size_t>(bd.num_dofs));
        CHECK(js[0]->at("name") == "root_x");
        CHECK(js[0]->at("type") == "slide");
        CHECK(vec3_of(js[0]->at("axis")) == Eigen::Vector3d::UnitX());
        CHECK(js[1]->at("name") == "root_z");
        CHECK(vec3_of(js[1]->at("axis")) == Eigen::Vector3d::UnitZ());
        CHECK(js[2]->at("name") == "root_pitch");
        CHECK(js[2]->at("type") == "hinge");
        CHECK(vec3_of(js[2]->at("axis")) == Eigen::Vector3d::UnitY());
        k0 = 3;
      }
      if constexpr (Root::nv == 6) {
        if (bd.joint_offset.isZero(0.0)) {
          CHECK(kids(e, "freejoint").size() == 1u);
        } else {  // slides x, y, z + ball: the free joint would ignore the offset
          CHECK(kids(e, "freejoint").empty());
          REQUIRE(js.size() == 4 + static_cast<std::size_t>(bd.num_dofs));
          for (int a = 0; a < 3; ++a) {
            CHECK(js[a]->at("type") == "slide");
            CHECK(vec3_of(js[a]->at("axis")) == Eigen::Vector3d::Unit(a));
          }
          CHECK(js[3]->at("name") == "root");
          CHECK(js[3]->at("type") == "ball");
          k0 = 4;
        }
      } else {
        CHECK(kids(e, "freejoint").empty());
      }
    } else {
      CHECK(kids(e, "freejoint").empty());
    }
    REQUIRE(js.size() == k0 + static_cast<std::size_t>(bd.num_dofs));
    for (int d = 0; d < bd.num_dofs; ++d) {
      const joint_dof& j = m.dofs[bd.first_dof + d];
      const xml_element& je = *js[k0 + d];
      CHECK(je.at("name") == j.name);
      CHECK(je.at("type") == "hinge");
      CHECK(vec3_of(je.at("pos")) == Eigen::Vector3d::Zero());
      CHECK(vec3_of(je.at("axis")) == j.axis);
      const bool finite_range = j.limit.lower > -1e8 || j.limit.upper < 1e8;
      if (opt.joint_limits && finite_range && j.limit.lower < j.limit.upper) {
        CHECK(je.at("limited") == "true");
        CHECK(numbers(je.at("range")) == std::vector<double>{j.limit.lower, j.limit.upper});
      } else {
        CHECK(je.at("limited") == "false");
      }
      dof_order_in_file.push_back(bd.first_dof + d);
    }
    n_joints += js.size();
    visual_shapes += opt.visual_geoms ? bd.shapes.size() : 0;
  }
  CHECK(all(world, "joint").size() == n_joints);  // not the <default> joint
  const bool free = Root::nv == 6 && m.bodies[0].joint_offset.isZero(0.0);
  const int root_joints = Root::nv == 3 ? 3 : (Root::nv == 6 && !free ? 4 : 0);
  CHECK(n_joints == static_cast<std::size_t>(m.num_joint_dofs() + root_joints));
  CHECK(all(doc, "freejoint").size() == (free ? 1u : 0u));
  CHECK(dof_order_in_file == mjcf_dof_order(m));

  // Geoms: floor + shapes + contact spheres. Sites: one per contact point.
  const std::size_t ncp = m.contact_points.size();
  const auto geoms = all(world, "geom");  // not the <default> geom
  CHECK(geoms.size() ==
        (opt.include_floor ? 1 : 0) + visual_shapes + (opt.contact_geoms ? ncp : 0));
  // The default <site> in <default> is not a site of the model.
  CHECK(all(world, "site").size() == (opt.contact_sites ? ncp : 0));
  std::size_t floors = 0, spheres = 0;
  for (const auto* g : geoms) {
    if (g->has("name") && g->at("name") == "floor") {
      ++floors;
      CHECK(g->at("type") == "plane");
    } else if (g->has("name")) {
      ++spheres;
      CHECK(g->at("type") == "sphere");
      CHECK(g->at("contype") == "1");
      CHECK(g->at("conaffinity") == "0");
      CHECK(std::strtod(g->at("size").c_str(), nullptr) == opt.contact_geom_radius);
    }
  }
  CHECK(floors == (opt.include_floor ? 1u : 0u));
  CHECK(spheres == (opt.contact_geoms ? ncp : 0u));
  const auto motors = all(doc, "motor");
  CHECK(motors.size() == (opt.actuators ? m.dofs.size() : 0u));
  for (std::size_t j = 0; j < motors.size(); ++j) {  // actuators in gaitsynth DOF order
    CHECK(motors[j]->at("joint") == m.dofs[j].name);
    CHECK(motors[j]->at("gear") == "1");
    if (m.dofs[j].torque_limit < 1e8)
      CHECK(numbers(motors[j]->at("ctrlrange")) ==
            std::vector<double>{-m.dofs[j].torque_limit, m.dofs[j].torque_limit});
  }
  CHECK(all(doc, "key").size() == (opt.keyframe_q.size() > 0 ? 1u : 0u));
}

struct option_case {
  const char* what;
  mjcf_options opt;
};
std::vector<option_case> option_cases() {
  std::vector<option_case> c;
  c.push_back({"defaults", {}});
  mjcf_options peer;
  peer.contact_geoms = true;
  peer.timestep = 1.0 / 3000.0;
  c.push_back({"contact geoms", peer});
  mjcf_options bare;
  bare.include_floor = false;
  bare.visual_geoms = false;
  bare.contact_sites = false;
  bare.joint_limits = false;
  bare.actuators = false;
  c.push_back({"bare", bare});
  return c;
}

}  // namespace

TEST_CASE("the MJCF of every test model is well-formed and mirrors the model", "[io][mjcf]") {
  std::mt19937 rng(7);
  const auto planar = mjcf_test::planar_biped7();
  const auto humanoid = mjcf_test::humanoid3d();
  const auto arm = mjcf_test::fixed_arm();
  const auto tree = mjcf_test::random_tree<floating_root>(rng, 12);
  const auto ptree = mjcf_test::random_tree<planar_root>(rng, 9);
  auto offset_tree = mjcf_test::random_tree<floating_root>(rng, 6);
  offset_tree.bodies[0].joint_offset = Eigen::Vector3d(0.1, -0.2, 0.9);
  auto offset_planar = planar;
  offset_planar.bodies[0].joint_offset = Eigen::Vector3d(0.0, 0.0, 1.1);
  for (const auto& oc : option_cases()) {
    INFO("options: " << oc.what);
    check_structure(planar, oc.opt);
    check_structure(humanoid, oc.opt);
    check_structure(arm, oc.opt);
    check_structure(tree, oc.opt);
    check_structure(ptree, oc.opt);
    check_structure(offset_tree, oc.opt);
    check_structure(offset_planar, oc.opt);
  }
}

TEST_CASE("the MJCF of every built-in character is well-formed and mirrors it", "[io][mjcf]") {
  mjcf_options peer;
  peer.contact_geoms = true;
  for (const mjcf_options& o : {mjcf_options{}, peer}) {
    check_structure(sharon2005_human7(), o);
    check_structure(sharon2005_human16(), o);
    for (wang2009_shape s : wang2009_shapes) check_structure(wang2009_humanoid(s), o);
    check_structure(wang2012_humanoid(), o);
    check_structure(wu2010_biped(), o);
  }
}

TEST_CASE("the MJCF reader refuses what XML or MJCF does not allow", "[io][mjcf]") {
  CHECK(parse("<mujoco model='m'>\n  <!-- a=\"b\"c -->\n  <option a=\"1\" b='2'/>\n</mujoco>")
            .children.at(0)
            .at("b") == "2");
  CHECK_THROWS_WITH(parse("<mujoco><option a=\"1\"b=\"2\"/></mujoco>"), Contains("whitespace"));
  CHECK_THROWS_WITH(parse("<mujoco><option a='1'b='2'/></mujoco>"), Contains("whitespace"));
  CHECK_THROWS_WITH(parse("<mujoco><body>x</body></mujoco>"), Contains("text content in <body>"));
  CHECK_THROWS(parse("<mujoco><body a=\"1\" a=\"2\"/></mujoco>"));
  CHECK_THROWS(parse("<mujoco><body></mujoco>"));
  CHECK_THROWS(parse("<mujoco model=\"&nbsp;\"/>"));
  CHECK_THROWS(parse("<mujoco/><mujoco/>"));
}

TEST_CASE("principal axes reproduce an inertia tensor and respect the triangle inequality",
          "[io][mjcf]") {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Matrix3d R =
        Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    const Eigen::Matrix3d I =
        mjcf_test::box_inertia(1.0 + k, Eigen::Vector3d(0.05, 0.1, 0.02 + 0.003 * k), R);
    const auto p = mjcf_principal_axes(I);
    CHECK_FALSE(p.identity);
    CHECK(std::abs(p.rotation.norm() - 1.0) <= 1e-15);
    CHECK(p.rotation.w() >= 0);
    const Eigen::Matrix3d Rp = p.rotation.toRotationMatrix();
    CHECK((Rp * p.moments.asDiagonal() * Rp.transpose() - I).cwiseAbs().maxCoeff() <=
          1e-14 * I.cwiseAbs().maxCoeff());
  }
  // Diagonal: passed through bit-exact, no rotation.
  const auto d = mjcf_principal_axes(Eigen::Vector3d(0.1, 0.2, 0.25).asDiagonal());
  CHECK(d.identity);
  CHECK(d.moments == Eigen::Vector3d(0.1, 0.2, 0.25));
  // A thin rod violating A + B >= C by rounding only is clamped onto the inequality.
  const auto rod = mjcf_principal_axes(Eigen::Vector3d(0.1, 1e-18, 0.1 + 1e-17).asDiagonal());
  CHECK(rod.moments[2] <= rod.moments[0] + rod.moments[1]);
  CHECK(rod.moments[2] == Approx(0.1).epsilon(1e-15));
}

TEST_CASE("the humanoid test model has the peer's 16 foot contacts", "[io][mjcf]") {
  const auto h = mjcf_test::humanoid3d();
  CHECK(h.num_joint_dofs() == 28);
  CHECK(h.contact_points.size() == 16);
  mjcf_options o;
  o.contact_geoms = true;
  const auto doc = parse(to_mjcf_string(h, o));
  std::size_t n = 0;
  for (const auto* g : all(doc, "geom")) n += g->has("group") && g->at("group") == "3";
  CHECK(n == 16);
}

TEST_CASE("the body order is depth-first and the q/v maps are its permutation", "[io][mjcf]") {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const auto m = mjcf_test::random_tree<floating_root>(rng, 10 + trial);
    const auto order = mjcf_body_order(m);
    REQUIRE(static_cast<int>(order.size()) == m.num_bodies());
    // Depth-first: every subtree is a contiguous block starting at its root.
    std::vector<int> pos(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) pos[order[k]] = static_cast<int>(k);
    std::vector<int> subtree(order.size(), 1);
    for (int i = m.num_bodies() - 1; i > 0; --i) subtree[m.bodies[i].parent] += subtree[i];
    for (int i = 1; i < m.num_bodies(); ++i) {
      const int p = m.bodies[i].parent;
      CHECK(pos[p] < pos[i]);
      CHECK(pos[i] + subtree[i] <= pos[p] + subtree[p]);
    }
    CHECK(order[0] == 0);
    // The maps are permutations, identity on the root block, consistent with the DOF order.
    const auto qi = mjcf_qpos_index(m), vi = mjcf_qvel_index(m);
    REQUIRE(static_cast<int>(qi.size()) == m.nq());
    REQUIRE(static_cast<int>(vi.size()) == m.nv());
    for (int i = 0; i < 7; ++i) CHECK(qi[i] == i);
    for (int i = 0; i < 6; ++i) CHECK(vi[i] == i);
    const auto dofs = mjcf_dof_order(m);
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      CHECK(qi[7 + k] == 7 + dofs[k]);
      CHECK(vi[6 + k] == 6 + dofs[k]);
    }
    const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(m.nq(), 1.0, m.nq());
    const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(m.nv(), -3.0, m.nv());
    const Eigen::VectorXd qm = to_mjcf_qpos(m, q), vm = to_mjcf_qvel(m, v);
    for (int k = 0; k < m.nq(); ++k) CHECK(qm[k] == q[qi[k]]);
    for (int k = 0; k < m.nv(); ++k) CHECK(vm[k] == v[vi[k]]);
    CHECK(from_mjcf_qpos(m, qm) == q);
    CHECK(from_mjcf_qvel(m, vm) == v);
  }
  const auto planar = mjcf_test::planar_biped7();
  // torso, lthigh, rthigh, lshin, rshin, lfoot, rfoot -> torso, lthigh, lshin, lfoot, rthigh, ...
  CHECK(mjcf_body_order(planar) == std::vector<int>{0, 1, 3, 5, 2, 4, 6});
  CHECK(mjcf_dof_order(planar) == std::vector<int>{0, 2, 4, 1, 3, 5});
  CHECK_THROWS_WITH(to_mjcf_qpos(planar, Eigen::VectorXd::Zero(5)), Contains("wrong size"));
  CHECK_THROWS_WITH(from_mjcf_qvel(planar, Eigen::VectorXd::Zero(10)), Contains("wrong size"));
}

TEST_CASE("the keyframe holds q and v in MuJoCo's order", "[io][mjcf]") {
  const auto m = mjcf_test::humanoid3d();
  mjcf_options o;
  o.keyframe_q = neutral_configuration(m);
  o.keyframe_q[2] = 0.93;
  for (int j = 0; j < m.num_joint_dofs(); ++j) o.keyframe_q[7 + j] = 0.01 * (j + 1);
  o.keyframe_v = Eigen::VectorXd::LinSpaced(m.nv(), 0.5, 2.0);
  const auto doc = parse(to_mjcf_string(m, o));
  const auto keys = all(doc, "key");
  REQUIRE(keys.size() == 1);
  const auto qpos = numbers(keys[0]->at("qpos"));
  const auto qvel = numbers(keys[0]->at("qvel"));
  const Eigen::VectorXd eq = to_mjcf_qpos(m, o.keyframe_q), ev = to_mjcf_qvel(m, o.keyframe_v);
  CHECK(qpos == std::vector<double>(eq.data(), eq.data() + eq.size()));
  CHECK(qvel == std::vector<double>(ev.data(), ev.data() + ev.size()));

  o.keyframe_v.resize(0);  // v defaults to zero
  const auto doc2 = parse(to_mjcf_string(m, o));
  const auto k2 = all(doc2, "key");
  CHECK(numbers(k2.at(0)->at("qvel")) == std::vector<double>(m.nv(), 0.0));
}

TEST_CASE("XML special characters in names are escaped and read back", "[io][mjcf]") {
  model_builder<planar_root> b("a <b> & \"c\" 'd'");
  b.add_body({.name = "trunk & co", .mass = 1, .inertia = mjcf_test::box_inertia(1, {.1, .1, .1})});
  b.add_body({.name = "<leg>",
              .parent = "trunk & co",
              .mass = 1,
              .inertia = mjcf_test::box_inertia(1, {.1, .1, .1}),
              .dofs = {{.name = "hip \"x\""}}});
  b.add_contact_point({.name = "it's a toe", .body = "<leg>"});
  const auto m = b.build();
  mjcf_options o;
  o.contact_geoms = true;
  const std::string text = to_mjcf_string(m, o);
  CHECK_THAT(text, Contains("&amp;"));
  CHECK_THAT(text, Contains("&lt;leg&gt;"));
  CHECK_THAT(text, Contains("&quot;x&quot;"));
  CHECK_THAT(text, Contains("it&apos;s"));
  const auto doc = parse(text);
  CHECK(doc.at("model") == "a <b> & \"c\" 'd'");
  const auto bodies = all(doc, "body");
  REQUIRE(bodies.size() == 2);
  CHECK(bodies[0]->at("name") == "trunk & co");
  CHECK(bodies[1]->at("name") == "<leg>");
  CHECK(kids(*bodies[1], "joint").at(0)->at("name") == "hip \"x\"");
  CHECK(all(doc, "motor").at(0)->at("joint") == "hip \"x\"");
  CHECK(kids(*bodies[1], "site").at(0)->at("name") == "it's a toe");
}

TEST_CASE("names XML or MuJoCo cannot hold are rejected", "[io][mjcf]") {
  const Eigen::Matrix3d I = mjcf_test::box_inertia(1, {.1, .1, .1});
  std::ostringstream os;
  SECTION("control character in a body name") {
    model_builder<fixed_root> b("m");
    b.add_body({.name = std::string("bad\x01name"), .mass = 1, .inertia = I});
    const auto m = b.build();
    CHECK_THROWS_AS(write_mjcf(m, os), std::invalid_argument);
    CHECK_THROWS_WITH(write_mjcf(m, os), Contains("control character") && Contains("body"));
    CHECK(os.str().empty());  // nothing written
  }
  SECTION("newline in a DOF name") {
    model_builder<fixed_root> b("m");
    b.add_body({.name = "base", .mass = 1, .inertia = I});
    b.add_body({.name = "arm",
                .parent = "base",
                .mass = 1,
                .inertia = I,
                .dofs = {{.name = "sh\noulder"}}});
    CHECK_THROWS_WITH(write_mjcf(b.build(), os), Contains("sh\noulder"));
  }
  SECTION("a body called world clashes with MuJoCo's world body") {
    model_builder<fixed_root> b("m");
    b.add_body({.name = "world", .mass = 1, .inertia = I});
    CHECK_THROWS_WITH(write_mjcf(b.build(), os), Contains("'world'") && Contains("body name"));
  }
  SECTION("a DOF called root clashes with the free joint") {
    model_builder<floating_root> b("m");
    b.add_body({.name = "base", .mass = 1, .inertia = I});
    b.add_body(
        {.name = "arm", .parent = "base", .mass = 1, .inertia = I, .dofs = {{.name = "root"}}});
    CHECK_THROWS_WITH(write_mjcf(b.build(), os), Contains("joint name 'root'"));
  }
  SECTION("a contact point called floor clashes with the floor geom only when it is a geom") {
    model_builder<fixed_root> b("m");
    b.add_body({.name = "base", .mass = 1, .inertia = I});
    b.add_contact_point({.name = "floor", .body = "base"});
    const auto m = b.build();
    CHECK_NOTHROW(write_mjcf(m, os));  // only a site
    mjcf_options o;
    o.contact_geoms = true;
    CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("geom name 'floor'"));
    o.include_floor = false;
    CHECK_NOTHROW(write_mjcf(m, os, o));
  }
}

TEST_CASE("bad exporter options throw std::invalid_argument naming them", "[io][mjcf]") {
  const auto m = mjcf_test::planar_biped7();
  std::ostringstream os;
  for (double dt : {0.0, -1e-3, std::nan(""), std::numeric_limits<double>::infinity()}) {
    mjcf_options o;
    o.timestep = dt;
    CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("timestep"));
  }
  mjcf_options o;
  o.friction = 0;
  CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("friction"));
  o = {};
  o.contact_geoms = true;
  o.contact_geom_radius = -0.01;
  CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("contact_geom_radius"));
  o = {};
  o.keyframe_q = Eigen::VectorXd::Zero(m.nq() + 1);
  CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("keyframe_q") && Contains("expected 9"));
  o.keyframe_q = Eigen::VectorXd::Zero(m.nq());
  o.keyframe_q[4] = std::nan("");
  CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("keyframe_q") && Contains("element 4"));
  o.keyframe_q = Eigen::VectorXd::Zero(m.nq());
  o.keyframe_v = Eigen::VectorXd::Zero(2);
  CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("keyframe_v"));
  o = {};
  o.keyframe_v = Eigen::VectorXd::Zero(m.nv());
  CHECK_THROWS_WITH(write_mjcf(m, os, o), Contains("without keyframe_q"));
  auto bad = m;
  bad.gravity.x() = std::nan("");
  CHECK_THROWS_WITH(write_mjcf(bad, os), Contains("gravity"));
  CHECK(os.str().empty());
}

TEST_CASE("save_mjcf writes the same text to a file and reports unwritable paths", "[io][mjcf]") {
  const auto m = mjcf_test::humanoid3d();
  const auto dir = std::filesystem::temp_directory_path();
  const auto path =
      dir / ("gaitsynth_test_mjcf_" + std::to_string(std::random_device{}()) + ".xml");
  save_mjcf(m, path.string());
  std::ifstream f(path);
  std::stringstream content;
  content << f.rdbuf();
  CHECK(content.str() == to_mjcf_string(m));
  std::filesystem::remove(path);
  CHECK_THROWS_AS(save_mjcf(m, (dir / "no_such_dir_gaitsynth" / "x.xml").string()),
                  std::runtime_error);
  // A model that cannot be exported leaves no file behind.
  auto bad = m;
  bad.bodies[0].name = "world";
  CHECK_THROWS_AS(save_mjcf(bad, path.string()), std::invalid_argument);
  CHECK_FALSE(std::filesystem::exists(path));
}
