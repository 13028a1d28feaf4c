#pragma once
/// \file nearest_neighbor_json.hpp
/// Saving and loading nearest-neighbor controllers (controllers/nearest_neighbor.hpp) as JSON, so
/// an optimized controller can be kept in the repository and re-simulated without its optimization.
/// Needs nlohmann::json (Debian: nlohmann-json3-dev).
///
///     {
///       "format": "gaitsynth.nearest_neighbor/1",
///       "model": "sharon2005_human7",
///       "options": {"num_nodes": 12, "symmetric": true, "input": [...], "input_weights": [...],
///                   "free_dofs": [...], "max_advance": -1, "output": "joint_torque",
///                   "kp": [...], "kd": [...], "torque_limit": 370, "torso_servo": true,
///                   "torso_body": "", "left_hip": "lhip", "right_hip": "rhip",
///                   "torso_kp": 1000, "torso_kd": 100, "left_foot": "lfoot",
///                   "right_foot": "rfoot", "stance_from_contacts": true,
///                   "compensate_swing_hip": true, "period": 0, "first_node_time": 0},
///       "nodes": [ {"location": {"root_pitch": 0.05, "lhip": ...}, "output": {"lhip": ...},
///                   "torso_pitch": 0.02, "stance": "right"},
///                  ...,
///                  {"mirror_of": 0, ...} ],       // derived nodes: written for reading, ignored
///       "info": { ... }                            // free-form (optimization record)
///     }
///
/// Angles are radians, written as the shortest decimals that read back exactly, so a saved
/// controller replays bit for bit. Errors are std::invalid_argument messages naming the source,
/// the location and the value.
#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/controllers/nearest_neighbor.hpp"
#include "gaitsynth/detail/json_text.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"

namespace gaitsynth {

namespace detail {
inline const char* stance_name(stance_side s) {
  return s == stance_side::left ? "left" : (s == stance_side::right ? "right" : "none");
}
inline const char* command_kind_name(command_kind k) {
  return k == command_kind::joint_torque
             ? "joint_torque"
             : (k == command_kind::joint_target ? "joint_target" : "excitation");
}
}  // namespace detail

/// The controller as JSON. `info` (any JSON object) is stored under "info".
template <root_joint Root>
nlohmann::ordered_json nearest_neighbor_to_json(const model<Root>& m,
                                                const nearest_neighbor_controller<Root>& c,
                                                const nlohmann::ordered_json& info = {}) {
  using J = nlohmann::ordered_json;
  const auto& o = c.opts();
  J j;
  j["format"] = "gaitsynth.nearest_neighbor/1";
  j["model"] = m.name;
  J jo;
  jo["num_nodes"] = o.num_nodes;
  jo["symmetric"] = o.symmetric;
  jo["input"] = c.input_names();
  jo["input_weights"] = std::vector<double>(c.input_weights().data(),
                                            c.input_weights().data() + c.input_weights().size());
  std::vector<std::string> free = o.free_dofs;
  if (free.empty())
    for (const auto& d : m.dofs) free.push_back(d.name);
  jo["free_dofs"] = free;
  jo["max_advance"] = o.max_advance;
  jo["first_node_time"] = o.first_node_time;
  jo["output"] = detail::command_kind_name(o.output);
  jo["kp"] = std::vector<double>(c.kp().data(), c.kp().data() + c.kp().size());
  jo["kd"] = std::vector<double>(c.kd().data(), c.kd().data() + c.kd().size());
  jo["torque_limit"] = o.torque_limit;
  jo["torso_servo"] = o.torso_servo;
  jo["torso_body"] = o.torso_body;
  jo["left_hip"] = o.left_hip;
  jo["right_hip"] = o.right_hip;
  jo["torso_kp"] = o.torso_kp;
  jo["torso_kd"] = o.torso_kd;
  jo["left_foot"] = o.left_foot;
  jo["right_foot"] = o.right_foot;
  jo["stance_from_contacts"] = o.stance_from_contacts;
  jo["compensate_swing_hip"] = o.compensate_swing_hip;
  jo["period"] = o.period;
  j["options"] = jo;
  J nodes = J::array();
  for (int i = 0; i < c.num_nodes(); ++i) {
    const nn_node nd = c.node(i);
    J jn;
    if (i >= c.num_free_nodes()) jn["mirror_of"] = i - c.num_free_nodes();
    J loc;
    for (int k = 0; k < c.num_inputs(); ++k) loc[c.input_names()[k]] = nd.location[k];
    J out;
    for (int d = 0; d < m.num_joint_dofs(); ++d) out[m.dofs[d].name] = nd.output[d];
    jn["location"] = loc;
    jn["output"] = out;
    jn["torso_pitch"] = nd.torso_pitch;
    jn["stance"] = detail::stance_name(nd.stance);
    nodes.push_back(jn);
  }
  j["nodes"] = nodes;
  if (!info.is_null()) j["info"] = info;
  return j;
}

/// Rebuilds a controller from JSON for model m. Throws std::invalid_argument (keyframes_error)
/// naming the source, location and value.
template <root_joint Root>
nearest_neighbor_controller<Root> nearest_neighbor_from_json(
    const model<Root>& m, const nlohmann::json& j, const std::string& source = "<controller>") {
  const detail::keyframe_reader r(source);
  if (!j.is_object()) r.fail("", "expected a JSON object, got " + std::string(j.type_name()));
  if (!j.contains("format") || j["format"] != "gaitsynth.nearest_neighbor/1")
    r.fail("format", "expected \"gaitsynth.nearest_neighbor/1\", got " +
                         (j.contains("format") ? detail::json_short(j["format"]) : "nothing"));
  if (j.contains("model") && j["model"] != m.name)
    r.fail("model",
           "file is for model " + j["model"].dump() + ", but the model is '" + m.name + "'");
  if (!j.contains("options")) r.fail("options", "missing object");
  if (!j["options"].is_object())
    r.fail("options", "expected an object, got " + std::string(j["options"].type_name()));
  const auto& jo = j["options"];
  // The options nearest_neighbor_to_json writes: another name is a typo, not a default to use.
  // clang-format off
  static const std::vector<std::string> known_options = {
      "num_nodes", "symmetric", "input", "input_weights", "free_dofs", "max_advance",
      "first_node_time", "output", "kp", "kd", "torque_limit", "torso_servo", "torso_body",
      "left_hip", "right_hip", "torso_kp", "torso_kd", "left_foot", "right_foot",
      "stance_from_contacts", "compensate_swing_hip", "period"};
  // clang-format on
  for (auto it = jo.begin(); it != jo.end(); ++it)
    if (std::find(known_options.begin(), known_options.end(), it.key()) == known_options.end())
      r.fail("options." + it.key(), "unknown option '" + it.key() +
                                        "' (known: " + detail::join_names(known_options) + ")");
  nearest_neighbor_options o;
  auto num = [&](const char* key, double& x) {
    if (jo.contains(key)) x = r.number(jo[key], std::string("options.") + key);
  };
  auto integer = [&](const char* key, int& x) {
    if (!jo.contains(key)) return;
    const auto& v = jo[key];
    if (!v.is_number_integer())
      r.fail(std::string("options.") + key, "expected an integer, got " + detail::json_short(v));
    if (v.is_number_unsigned()
            ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT_MAX)
            : (v.get<std::int64_t>() < INT_MIN || v.get<std::int64_t>() > INT_MAX))
      r.fail(std::string("options.") + key, v.dump() + " is out of range for an int");
    x = v.get<int>();
  };
  auto boolean = [&](const char* key, bool& x) {
    if (!jo.contains(key)) return;
    if (!jo[key].is_boolean())
      r.fail(std::string("options.") + key,
             "expected true/false, got " + detail::json_short(jo[key]));
    x = jo[key].get<bool>();
  };
  auto string = [&](const char* key, std::string& x) {
    if (!jo.contains(key)) return;
    if (!jo[key].is_string())
      r.fail(std::string("options.") + key,
             "expected a string, got " + detail::json_short(jo[key]));
    x = jo[key].get<std::string>();
  };
  auto strings = [&](const char* key, std::vector<std::string>& x) {
    if (!jo.contains(key)) return;
    const auto& a = jo[key];
    if (!a.is_array())
      r.fail(std::string("options.") + key,
             "expected an array of strings, got " + std::string(a.type_name()));
    x.clear();
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!a[i].is_string())
        r.fail(std::string("options.") + key + "[" + std::to_string(i) + "]",
               "expected a string, got " + detail::json_short(a[i]));
      x.push_back(a[i].get<std::string>());
    }
  };
  auto numbers = [&](const char* key, std::vector<double>& x) {
    if (!jo.contains(key)) return;
    const auto& a = jo[key];
    if (!a.is_array())
      r.fail(std::string("options.") + key,
             "expected an array of numbers, got " + std::string(a.type_name()));
    x.clear();
    for (std::size_t i = 0; i < a.size(); ++i)
      x.push_back(r.number(a[i], std::string("options.") + key + "[" + std::to_string(i) + "]"));
  };
  integer("num_nodes", o.num_nodes);
  boolean("symmetric", o.symmetric);
  strings("input", o.input);
  numbers("input_weights", o.input_weights);
  strings("free_dofs", o.free_dofs);
  integer("max_advance", o.max_advance);
  num("first_node_time", o.first_node_time);
  std::string output = "joint_torque";
  string("output", output);
  if (output == "joint_torque")
    o.output = command_kind::joint_torque;
  else if (output == "joint_target")
    o.output = command_kind::joint_target;
  else
    r.fail("options.output",
           "expected \"joint_torque\" or \"joint_target\", got \"" + output + "\"");
  numbers("kp", o.kp);
  numbers("kd", o.kd);
  for (const auto& [key, gains] : {std::pair{"kp", &o.kp}, std::pair{"kd", &o.kd}})
    if (!gains->empty() && static_cast<int>(gains->size()) != m.num_joint_dofs())
      r.fail(std::string("options.") + key, "expected " + std::to_string(m.num_joint_dofs()) +
                                                " gains (one per joint DOF of model '" + m.name +
                                                "'), got " + std::to_string(gains->size()));
  num("torque_limit", o.torque_limit);
  boolean("torso_servo", o.torso_servo);
  string("torso_body", o.torso_body);
  string("left_hip", o.left_hip);
  string("right_hip", o.right_hip);
  num("torso_kp", o.torso_kp);
  num("torso_kd", o.torso_kd);
  string("left_foot", o.left_foot);
  string("right_foot", o.right_foot);
  boolean("stance_from_contacts", o.stance_from_contacts);
  boolean("compensate_swing_hip", o.compensate_swing_hip);
  num("period", o.period);

  if (!j.contains("nodes")) r.fail("nodes", "missing array");
  if (!j["nodes"].is_array())
    r.fail("nodes", "expected an array, got " + std::string(j["nodes"].type_name()));
  const auto& jn = j["nodes"];
  const int nfree = o.symmetric ? o.num_nodes / 2 : o.num_nodes;
  if (static_cast<int>(jn.size()) < nfree)
    r.fail("nodes", "expected at least " + std::to_string(nfree) + " nodes, got " +
                        std::to_string(jn.size()));
  // Input names: the file's, or the default the controller would build.
  std::vector<std::string> input = o.input;
  if (input.empty()) {
    if constexpr (Root::nq == 3) input.push_back("root_pitch");
    for (const auto& d : m.dofs) input.push_back(d.name);
  }
  std::vector<nn_node> nodes(nfree);
  for (int i = 0; i < nfree; ++i) {
    const std::string where = "nodes[" + std::to_string(i) + "]";
    const auto& n = jn[i];
    if (!n.is_object()) r.fail(where, "expected an object, got " + std::string(n.type_name()));
    if (n.contains("mirror_of"))
      r.fail(where, "the first " + std::to_string(nfree) + " nodes must be free (no mirror_of)");
    for (const char* key : {"location", "output"}) {
      if (!n.contains(key)) r.fail(where + "." + key, "missing object");
      if (!n[key].is_object())
        r.fail(where + "." + key, "expected an object, got " + std::string(n[key].type_name()));
    }
    nn_node& nd = nodes[i];
    // Unknown names first: a misspelt name is reported as itself, not as the name it misses.
    for (auto it = n["location"].begin(); it != n["location"].end(); ++it)
      if (std::find(input.begin(), input.end(), it.key()) == input.end())
        r.fail(where + ".location." + it.key(), "'" + it.key() + "' is not an input coordinate");
    nd.location.resize(static_cast<Eigen::Index>(input.size()));
    for (std::size_t k = 0; k < input.size(); ++k) {
      const std::string w = where + ".location." + input[k];
      if (!n["location"].contains(input[k])) r.fail(w, "missing");
      nd.location[static_cast<Eigen::Index>(k)] = r.number(n["location"][input[k]], w);
    }
    for (auto it = n["output"].begin(); it != n["output"].end(); ++it)
      if (m.find_dof(it.key()) < 0)
        r.fail(where + ".output." + it.key(), "unknown DOF name '" + it.key() + "'");
    nd.output.resize(m.num_joint_dofs());
    for (int d = 0; d < m.num_joint_dofs(); ++d) {
      const std::string w = where + ".output." + m.dofs[d].name;
      if (!n["output"].contains(m.dofs[d].name)) r.fail(w, "missing");
      nd.output[d] = r.number(n["output"][m.dofs[d].name], w);
    }
    nd.torso_pitch =
        n.contains("torso_pitch") ? r.number(n["torso_pitch"], where + ".torso_pitch") : 0.0;
    if (n.contains("stance") && !n["stance"].is_string())
      r.fail(where + ".stance",
             "expected \"left\", \"right\" or \"none\", got " + detail::json_short(n["stance"]));
    const std::string st = n.contains("stance") ? n["stance"].get<std::string>() : "none";
    if (st == "left")
      nd.stance = stance_side::left;
    else if (st == "right")
      nd.stance = stance_side::right;
    else if (st == "none")
      nd.stance = stance_side::none;
    else
      r.fail(where + ".stance", "expected left, right or none, got \"" + st + "\"");
  }
  try {
    return nearest_neighbor_controller<Root>(m, o, std::move(nodes));
  } catch (const std::invalid_argument& e) {
    throw keyframes_error(source + ": " + e.what());
  }
}

/// Writes the controller JSON to a file (creating parent directories).
template <root_joint Root>
void save_nearest_neighbor(const std::filesystem::path& path, const model<Root>& m,
                           const nearest_neighbor_controller<Root>& c,
                           const nlohmann::ordered_json& info = {}) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path.string() + ": cannot write controller file");
  out << nearest_neighbor_to_json(m, c, info).dump(2) << "\n";
}

/// Loads a controller file. Throws keyframes_error (std::invalid_argument) naming what is wrong.
template <root_joint Root>
nearest_neighbor_controller<Root> load_nearest_neighbor(const model<Root>& m,
                                                        const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw keyframes_error(path.string() + ": cannot open controller file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string source = path.filename().string();
  return nearest_neighbor_from_json(m, detail::parse_json_text<keyframes_error>(ss.str(), source),
                                    source);
}

}  // namespace gaitsynth
