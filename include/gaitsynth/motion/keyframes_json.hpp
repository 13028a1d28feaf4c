#pragma once
/// \file keyframes_json.hpp
/// Reading and writing cyclic keyframe target motions (motion/keyframes.hpp) as JSON, a format
/// meant to be written by hand. Needs nlohmann::json (Debian: nlohmann-json3-dev).
///
/// Example (a symmetric walk: one step listed, the other step is its mirror image):
///
///     {
///       "format": "gaitsynth.keyframes/1",
///       "model": "sharon2005_human7",          // optional; if given it must match model.name
///       "units": "degrees",                    // angles in degrees (default) or "radians"
///       "symmetric": true,                     // odd steps are the left/right mirror image
///       "stance": "right",                     // stance leg of the listed step (left/right/none)
///       "end_time": 0.5,                       // s: the listed step wraps to its first keyframe
///       "advance": {"root_x": 0.6},            // root displacement per listed step, m
///       "defaults": {"root_pitch": 0},         // values of DOFs a keyframe leaves out
///       "keyframes": [
///         {"time": 0.0, "pose": {"root_x": 0, "root_z": 1.2, "rhip": 20, "rknee": 5, ...}},
///         {"time": 0.2, "pose": [0.1, 1.21, 0, ...]}   // or all nq values in q order
///       ]
///     }
///
/// Pose names are the model's joint DOF names plus the root coordinates: root_x, root_z, root_pitch
/// (planar root; root_pitch is an angle) or root_x, root_y, root_z, root_qw, root_qx, root_qy,
/// root_qz (floating root; the quaternion is unitless and defaults to identity). Translations are
/// in metres whatever the units. Every error is a `keyframes_error` (a std::invalid_argument) whose
/// message starts with the source (file name) and the JSON location, e.g.
///     walk.json: keyframes[2].pose.lkne: unknown DOF name 'lkne' (known: root_x, root_z, ...)
/// (comments as above are not JSON; real files have none).
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/detail/json_text.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/motion/keyframes.hpp"

namespace gaitsynth {

/// Malformed or inconsistent keyframe file. The message names the source, the location and the
/// value.
class keyframes_error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace detail {

/// Names of the configuration coordinates as they appear in keyframe files (size nq).
template <root_joint Root>
std::vector<std::string> keyframe_coordinate_names(const model<Root>& m) {
  std::vector<std::string> names;
  if constexpr (Root::nq == 3) {
    names = {"root_x", "root_z", "root_pitch"};
  } else if constexpr (Root::nq == 7) {
    names = {"root_x", "root_y", "root_z", "root_qw", "root_qx", "root_qy", "root_qz"};
  }
  for (const auto& d : m.dofs) names.push_back(d.name);
  return names;
}

/// True when coordinate i is an angle (converted by "units"); translations and quaternion parts are
/// not.
template <root_joint Root>
bool keyframe_coordinate_is_angle(int i) {
  if constexpr (Root::nq == 3)
    return i >= 2;
  else
    return i >= Root::nq;
}

inline std::string join_names(const std::vector<std::string>& n) {
  std::string s;
  for (std::size_t i = 0; i < n.size(); ++i) s += (i ? ", " : "") + n[i];
  return s;
}

/// Shortest decimal that reads back as x (0.3, not 0.29999999999999999).
inline std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

inline std::string json_short(const nlohmann::json& j) {
  std::string s = j.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

class keyframe_reader {
 public:
  explicit keyframe_reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw keyframes_error(source_ + ": " + (where.empty() ? std::string("(top level)") : where) +
                          ": " + what);
  }

  double number(const nlohmann::json& j, const std::string& where) const {
    if (!j.is_number())
      fail(where, "expected a number, got " + json_short(j) + " (" + j.type_name() + ")");
    const double x = j.get<double>();
    if (!std::isfinite(x)) fail(where, "not finite");
    return x;
  }

 private:
  std::string source_;
};

}  // namespace detail

/// Builds a keyframe motion for model `m` from parsed JSON. `source` names the origin in messages
/// (usually the file name). Throws keyframes_error.
template <root_joint Root>
keyframe_motion<Root> keyframes_from_json(const model<Root>& m, const nlohmann::json& j,
                                          const std::string& source = "<keyframes>") {
  using nlohmann::json;
  const detail::keyframe_reader r(source);
  if (!j.is_object()) r.fail("", "expected a JSON object, got " + std::string(j.type_name()));

  static const std::vector<std::string> known_keys = {
      "format",   "model",   "description", "units",     "symmetric", "stance",
      "end_time", "advance", "defaults",    "keyframes", "figure",    "notes"};
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (const auto& k : known_keys) ok = ok || it.key() == k;
    if (!ok)
      r.fail(it.key(),
             "unknown key '" + it.key() + "' (known: " + detail::join_names(known_keys) + ")");
  }
  if (j.contains("format")) {
    const auto& f = j["format"];
    if (!f.is_string() || f.get<std::string>() != "gaitsynth.keyframes/1")
      r.fail("format", "expected \"gaitsynth.keyframes/1\", got " + detail::json_short(f));
  }
  if (j.contains("model")) {
    const auto& mn = j["model"];
    if (!mn.is_string()) r.fail("model", "expected a string, got " + detail::json_short(mn));
    if (mn.get<std::string>() != m.name)
      r.fail("model", "file is for model '" + mn.get<std::string>() + "', but the model is '" +
                          m.name + "'");
  }
  double angle_scale = std::numbers::pi / 180.0;
  if (j.contains("units")) {
    const auto& u = j["units"];
    const std::string us = u.is_string() ? u.get<std::string>() : std::string();
    if (us == "degrees")
      angle_scale = std::numbers::pi / 180.0;
    else if (us == "radians")
      angle_scale = 1.0;
    else
      r.fail("units", "expected \"degrees\" or \"radians\", got " + detail::json_short(u));
  }
  bool symmetric = false;
  if (j.contains("symmetric")) {
    if (!j["symmetric"].is_boolean())
      r.fail("symmetric", "expected true or false, got " + detail::json_short(j["symmetric"]));
    symmetric = j["symmetric"].get<bool>();
  }
  stance_side stance = stance_side::none;
  if (j.contains("stance")) {
    const auto& s = j["stance"];
    const std::string ss = s.is_string() ? s.get<std::string>() : std::string();
    if (ss == "left")
      stance = stance_side::left;
    else if (ss == "right")
      stance = stance_side::right;
    else if (ss == "none")
      stance = stance_side::none;
    else
      r.fail("stance", "expected \"left\", \"right\" or \"none\", got " + detail::json_short(s));
  }

  const std::vector<std::string> names = detail::keyframe_coordinate_names(m);
  const int nq = m.nq();
  auto index_of = [&](const std::string& name, const std::string& where) {
    for (int i = 0; i < nq; ++i)
      if (names[i] == name) return i;
    r.fail(where, "unknown DOF name '" + name + "' (model '" + m.name +
                      "' has: " + detail::join_names(names) + ")");
  };
  auto value_of = [&](int i, double x) {
    return detail::keyframe_coordinate_is_angle<Root>(i) ? x * angle_scale : x;
  };

  // Defaults for coordinates a keyframe leaves out. A floating root's quaternion defaults to
  // identity.
  std::vector<double> defaults(nq, std::numeric_limits<double>::quiet_NaN());
  if constexpr (Root::nq == 7) defaults[3] = 1.0, defaults[4] = defaults[5] = defaults[6] = 0.0;
  if (j.contains("defaults")) {
    const auto& d = j["defaults"];
    if (!d.is_object())
      r.fail("defaults",
             "expected an object of DOF name: value, got " + std::string(d.type_name()));
    for (auto it = d.begin(); it != d.end(); ++it) {
      const std::string where = "defaults." + it.key();
      const int i = index_of(it.key(), where);
      defaults[i] = value_of(i, r.number(it.value(), where));
    }
  }

  if (!j.contains("end_time"))
    r.fail("end_time", "missing (time at which the listed keyframes wrap around, s)");
  const double end_time = r.number(j["end_time"], "end_time");

  Eigen::VectorXd advance = Eigen::VectorXd::Zero(Root::nq);
  if (j.contains("advance")) {
    const auto& a = j["advance"];
    if (!a.is_object())
      r.fail("advance",
             "expected an object such as {\"root_x\": 0.6}, got " + std::string(a.type_name()));
    for (auto it = a.begin(); it != a.end(); ++it) {
      const std::string where = "advance." + it.key();
      const int i = index_of(it.key(), where);
      if (i >= Root::nq || detail::keyframe_coordinate_is_angle<Root>(i) ||
          (Root::nq == 7 && i >= 3))
        r.fail(where, "only the root's translation can advance, not '" + it.key() + "'");
      advance[i] = r.number(it.value(), where);
    }
  }

  if (!j.contains("keyframes")) r.fail("keyframes", "missing");
  const auto& ks = j["keyframes"];
  if (!ks.is_array() || ks.empty())
    r.fail("keyframes", "expected a non-empty array of {\"time\": ..., \"pose\": ...}, got " +
                            (ks.is_array() ? std::string("[]") : std::string(ks.type_name())));
  std::vector<keyframe> frames;
  for (std::size_t k = 0; k < ks.size(); ++k) {
    const std::string where = "keyframes[" + std::to_string(k) + "]";
    const auto& kf = ks[k];
    if (!kf.is_object())
      r.fail(where,
             "expected an object with \"time\" and \"pose\", got " + std::string(kf.type_name()));
    for (auto it = kf.begin(); it != kf.end(); ++it)
      if (it.key() != "time" && it.key() != "pose" && it.key() != "name")
        r.fail(where + "." + it.key(), "unknown key '" + it.key() + "' (known: time, pose, name)");
    if (!kf.contains("time")) r.fail(where + ".time", "missing");
    keyframe f;
    f.time = r.number(kf["time"], where + ".time");
    if (k == 0 && f.time != 0.0)
      r.fail(where + ".time",
             "the first keyframe must be at time 0, got " + detail::json_short(kf["time"]));
    if (k > 0 && !(f.time > frames.back().time)) {
      r.fail(where + ".time", "times must increase: " + detail::shortest(f.time) +
                                  " s is not after keyframes[" + std::to_string(k - 1) +
                                  "].time = " + detail::shortest(frames.back().time) + " s");
    }
    if (!kf.contains("pose")) r.fail(where + ".pose", "missing");
    const auto& p = kf["pose"];
    f.q.resize(nq);
    if (p.is_array()) {
      if (static_cast<int>(p.size()) != nq)
        r.fail(where + ".pose", "wrong DOF count: model '" + m.name +
                                    "' has nq = " + std::to_string(nq) + " coordinates (" +
                                    detail::join_names(names) + "), got " +
                                    std::to_string(p.size()));
      for (int i = 0; i < nq; ++i)
        f.q[i] = value_of(i, r.number(p[i], where + ".pose[" + std::to_string(i) + "]"));
    } else if (p.is_object()) {
      std::vector<bool> set(nq, false);
      for (auto it = p.begin(); it != p.end(); ++it) {
        const std::string w = where + ".pose." + it.key();
        const int i = index_of(it.key(), w);
        f.q[i] = value_of(i, r.number(it.value(), w));
        set[i] = true;
      }
      for (int i = 0; i < nq; ++i) {
        if (set[i]) continue;
        if (std::isnan(defaults[i]))
          r.fail(where + ".pose",
                 "missing DOF '" + names[i] + "' (and no \"defaults\" entry for it)");
        f.q[i] = defaults[i];
      }
    } else {
      r.fail(where + ".pose", "expected an object {name: value} or an array of " +
                                  std::to_string(nq) + " numbers, got " + p.type_name());
    }
    frames.push_back(std::move(f));
  }
  if (!(end_time > frames.back().time)) {
    r.fail("end_time", "must be after the last keyframe's time " +
                           detail::shortest(frames.back().time) + " s, got " +
                           detail::shortest(end_time));
  }
  try {
    return keyframe_motion<Root>(m, std::move(frames), end_time, symmetric, advance, stance);
  } catch (const std::invalid_argument& e) {
    throw keyframes_error(source + ": " + e.what());
  }
}

/// Parses keyframes from a JSON string. Throws keyframes_error (also for malformed JSON, a number
/// too large for a double, a repeated key or nesting deeper than detail::max_json_depth: see
/// detail/json_text.hpp).
template <root_joint Root>
keyframe_motion<Root> parse_keyframes(const model<Root>& m, const std::string& text,
                                      const std::string& source = "<keyframes>") {
  return keyframes_from_json(m, detail::parse_json_text<keyframes_error>(text, source), source);
}

/// Loads a keyframe file. Throws keyframes_error for a missing/unreadable file or bad content.
template <root_joint Root>
keyframe_motion<Root> load_keyframes(const model<Root>& m, const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw keyframes_error(path.string() + ": cannot open keyframe file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_keyframes(m, ss.str(), path.filename().string());
}

/// Writes a keyframe motion as JSON (named poses, degrees, keys in reading order), readable by
/// keyframes_from_json.
template <root_joint Root>
nlohmann::ordered_json keyframes_to_json(const model<Root>& m, const keyframe_motion<Root>& motion,
                                         const std::string& description = "") {
  nlohmann::ordered_json j;
  j["format"] = "gaitsynth.keyframes/1";
  j["model"] = m.name;
  if (!description.empty()) j["description"] = description;
  j["units"] = "degrees";
  j["symmetric"] = motion.symmetric();
  j["stance"] = motion.stance() == stance_side::left
                    ? "left"
                    : (motion.stance() == stance_side::right ? "right" : "none");
  j["end_time"] = motion.end_time();
  const auto names = detail::keyframe_coordinate_names(m);
  nlohmann::ordered_json adv = nlohmann::ordered_json::object();
  for (int i = 0; i < Root::nq; ++i)
    if (motion.advance()[i] != 0.0) adv[names[i]] = motion.advance()[i];
  j["advance"] = adv;
  nlohmann::ordered_json ks = nlohmann::ordered_json::array();
  for (const auto& f : motion.keyframes()) {
    nlohmann::ordered_json pose = nlohmann::ordered_json::object();
    for (int i = 0; i < m.nq(); ++i)
      pose[names[i]] = detail::keyframe_coordinate_is_angle<Root>(i)
                           ? f.q[i] * 180.0 / std::numbers::pi
                           : f.q[i];
    nlohmann::ordered_json kf;
    kf["time"] = f.time;
    kf["pose"] = pose;
    ks.push_back(kf);
  }
  j["keyframes"] = ks;
  return j;
}

}  // namespace gaitsynth
