#pragma once
/// \file controllers/end_effector/planned_walk_json.hpp
/// Saving and loading an optimized planned_walk (Wu & Popovic 2010's cyclical controller) as JSON
/// (needs nlohmann::json), the format examples/wu2010_walk.cpp writes:
///
///     {
///       "controller": "planned_walk",
///       "symmetry": "mirrored_planner",
///       "parameter_names": ["omega0.t_e", ..., "pi1.rho", "h_max"],   // planned_walk's order
///       "parameters": [0.12, ...],
///       "controller_rate": 600, "stance_target": "touchdown", "helper_force": true,
///       "cost": 35.3, ...                                           // how it was made, kept
///     }
///
/// nlohmann::json writes doubles as the shortest decimals that read back exactly, so a saved
/// controller replays bit for bit.
/// Errors are std::invalid_argument (std::runtime_error for I/O) naming the file, the field and
/// the bad value.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_names.hpp"

namespace gaitsynth {

/// A saved planned_walk: its parameters by name and everything else the file says.
struct planned_walk_saved {
  std::vector<std::string> names;
  std::vector<double> values;
  nlohmann::json info = nlohmann::json::object();  ///< cost, h_max, controller_rate, ...
};

/// Writes names/x and the entries of `info` to `path` (through a temporary file and a rename, so
/// a reader never sees half a file). Throws std::invalid_argument for a size mismatch,
/// std::runtime_error if it cannot write.
inline void save_planned_walk(
    const std::filesystem::path& path, const std::vector<std::string>& names,
    std::span<const double> x, const nlohmann::ordered_json& info,
    planned_walk_symmetry symmetry = planned_walk_symmetry::mirrored_planner) {
  check_argument(names.size() == x.size(), "save_planned_walk: ", names.size(),
                 " parameter names but ", x.size(), " values");
  nlohmann::ordered_json j;
  j["controller"] = "planned_walk";
  j["paper"] = "Wu & Popovic 2010, Sec. 7-8";
  j["symmetry"] = name_of(planned_walk_symmetry_names, symmetry);
  j["parameter_names"] = names;
  j["parameters"] = std::vector<double>(x.begin(), x.end());
  for (const auto& [k, v] : info.items()) j[k] = v;
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << j.dump(2) << "\n";
    if (!out) throw std::runtime_error("save_planned_walk: cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

/// Reads `path`: a planned_walk controller (any symmetry; none recorded: mirrored_planner), names
/// and values of equal count, every value a finite number.
inline planned_walk_saved load_planned_walk(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw std::invalid_argument(path.string() + ": not JSON: " + e.what());
  }
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument(path.string() + ": " + what);
  };
  if (!j.is_object()) fail("not a saved controller (no JSON object)");
  if (!j.contains("controller") || j["controller"] != "planned_walk")
    fail("not a planned_walk controller (\"controller\": " +
         (j.contains("controller") ? j["controller"].dump() : std::string("missing")) + ")");
  if (j.contains("symmetry") &&
      !(j["symmetry"].is_string() &&
        value_of(planned_walk_symmetry_names, j["symmetry"].get<std::string>())))
    fail("symmetry " + j["symmetry"].dump() + " is not one of " +
         quoted_choices(planned_walk_symmetry_names));
  if (!j.contains("parameter_names") || !j["parameter_names"].is_array() ||
      !j.contains("parameters") || !j["parameters"].is_array())
    fail("needs the arrays \"parameter_names\" and \"parameters\"");
  planned_walk_saved s;
  for (const auto& n : j["parameter_names"]) {
    if (!n.is_string()) fail("a parameter name is not a string: " + n.dump());
    s.names.push_back(n.get<std::string>());
  }
  for (std::size_t i = 0; i < j["parameters"].size(); ++i) {
    const auto& v = j["parameters"][i];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail("parameter " + std::to_string(i) +
           (i < s.names.size() ? " (" + s.names[i] + ")" : std::string()) +
           " is not a finite number: " + v.dump());
    s.values.push_back(v.get<double>());
  }
  if (s.names.size() != s.values.size())
    fail(std::to_string(s.names.size()) + " parameter names but " +
         std::to_string(s.values.size()) + " values");
  for (const auto& [k, v] : j.items())
    if (k != "parameter_names" && k != "parameters") s.info[k] = v;
  return s;
}

/// The saved values in the order of `names` (a controller's parameter_names()). A saved "h_max"
/// that `names` lacks is dropped (a helper-force controller run without it); an "h_max" that
/// `names` wants and the file lacks comes from its "h_max" entry. Every other missing, unknown or
/// repeated name throws, naming the file and the parameter.
inline std::vector<double> planned_walk_values(const planned_walk_saved& s,
                                               const std::vector<std::string>& names,
                                               const std::filesystem::path& path) {
  std::map<std::string, double> by_name;
  for (std::size_t i = 0; i < s.names.size(); ++i) {
    if (!by_name.emplace(s.names[i], s.values[i]).second)
      throw std::invalid_argument(path.string() + ": parameter '" + s.names[i] + "' appears twice");
    if (s.names[i] != "h_max" && std::find(names.begin(), names.end(), s.names[i]) == names.end())
      throw std::invalid_argument(path.string() + ": unknown parameter '" + s.names[i] +
                                  "' = " + std::to_string(s.values[i]) + " (planned_walk has " +
                                  std::to_string(names.size()) + " parameters, " + names.front() +
                                  " ... " + names.back() + ")");
  }
  std::vector<double> x;
  x.reserve(names.size());
  for (const std::string& n : names) {
    const auto it = by_name.find(n);
    if (it != by_name.end()) {
      x.push_back(it->second);
    } else if (n == "h_max" && s.info.contains("h_max") && s.info["h_max"].is_number()) {
      x.push_back(s.info["h_max"].get<double>());
    } else {
      throw std::invalid_argument(path.string() + ": parameter '" + n + "' is missing (has " +
                                  std::to_string(s.names.size()) + " of the " +
                                  std::to_string(names.size()) + " parameters)");
    }
  }
  return x;
}

/// `base` with what the file records about how the controller ran: "controller_rate" (Hz, 0:
/// every physics step) as the period, "stance_target" ("planned_landing", "touchdown" or
/// "first_contact"), "half_cycle_timing" ("fixed" or "touchdown"),
/// "helper_force", "symmetry" and "pin_by" (Sec. 6.3's contact test: "frame_geometry" or "link").
/// Entries the file lacks leave base's values; a malformed one throws, named.
inline planned_walk_options saved_planned_walk_options(const planned_walk_saved& s,
                                                       const std::filesystem::path& path,
                                                       planned_walk_options base = {}) {
  auto fail = [&](const std::string& field, const nlohmann::json& v, const std::string& want) {
    throw std::invalid_argument(path.string() + ": " + field + " must be " + want + ", got " +
                                v.dump());
  };
  if (s.info.contains("controller_rate")) {
    const nlohmann::json& r = s.info["controller_rate"];
    if (!r.is_number() || !(r.get<double>() == 0.0 || r.get<double>() > 2.0))
      fail("controller_rate", r, "0 or above 2 Hz");
    base.period = r.get<double>() > 0.0 ? 1.0 / r.get<double>() : 0.0;
  }
  // An enum field: one of its table's names (planned_walk_names.hpp).
  auto read = [&](const char* field, const auto& table, auto& out) {
    if (!s.info.contains(field)) return;
    const nlohmann::json& v = s.info[field];
    const auto value = v.is_string() ? value_of(table, v.get<std::string>()) : std::nullopt;
    if (!value) fail(field, v, quoted_choices(table));
    out = *value;
  };
  read("stance_target", stance_foot_target_names, base.stance_target);
  read("half_cycle_timing", half_cycle_end_names, base.timing);
  read("symmetry", planned_walk_symmetry_names, base.symmetry);
  if (s.info.contains("helper_force")) {
    const nlohmann::json& v = s.info["helper_force"];
    if (!v.is_boolean()) fail("helper_force", v, "true or false");
    base.helper_force = v.get<bool>();
  }
  read("pin_by", pin_contact_names, base.lower.pin_by);
  return base;
}

}  // namespace gaitsynth
