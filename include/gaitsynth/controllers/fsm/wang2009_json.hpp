#pragma once
/// \file controllers/fsm/wang2009_json.hpp
/// Saving and loading an optimized wang2009_controller as JSON, so a walker can be kept in the
/// repository and re-simulated without its optimization. Needs nlohmann::json.
///
///     {
///       "paper": "Wang, Fleet & Hertzmann 2009",
///       "shape": "stocky",                 // models/wang2009.hpp preset
///       "target_speed": null,              // m/s, or null: E_user without it
///       "target_step_length": null,        // m, or null
///       "cost": 19.8,                      // eq. 16 over the optimized horizon
///       "parameters": {"s0_kp_swing_hip_x": 1000, ...},   // all 184, by name
///       "info": { ... }                    // free-form (how it was made), kept as is
///     }
///
/// nlohmann::json writes doubles as the shortest decimals that read back exactly, so a saved
/// controller replays bit for bit. Errors are std::invalid_argument naming the file, the field and
/// the bad value.
#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/detail/json_text.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct wang2009_saved_controller {
  std::string shape = "stocky";
  std::optional<double> target_speed, target_step_length;
  double cost = 0.0;
  std::vector<double> parameters;  ///< in the controller's order
  nlohmann::json info = nlohmann::json::object();
};

namespace detail {

/// The text of a controller file, parsed (detail/json_text.hpp); std::invalid_argument naming
/// `path`.
inline nlohmann::json read_wang2009_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  check_argument(in.good(), "cannot open controller file '", path, "'");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_json_text<std::invalid_argument>(text, path);
}

[[noreturn]] inline void wang2009_json_fail(const std::string& path, const std::string& field,
                                            const std::string& what) {
  throw std::invalid_argument(path + ": field '" + field + "': " + what);
}

/// A value of a controller file for messages: its JSON, cut at 60 characters.
inline std::string wang2009_json_value(const nlohmann::json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

/// v as a number, or std::invalid_argument naming `path`, `field` and the value. Finite: the text
/// has no NaN and json_text_problem refuses overflow.
inline double controller_json_number(const std::string& path, const nlohmann::json& v,
                                     const std::string& field) {
  if (!v.is_number())
    wang2009_json_fail(
        path, field,
        "expected a number, got " + wang2009_json_value(v) + " (" + v.type_name() + ")");
  return v.get<double>();
}

/// The "parameters" object of controller file j, in the order of `names`: an unknown, missing or
/// non-number parameter is refused naming the file, the field and the value.
inline std::vector<double> read_named_parameters(const std::string& path, const nlohmann::json& j,
                                                 const std::vector<std::string>& names) {
  if (!j.contains("parameters")) wang2009_json_fail(path, "parameters", "missing");
  const nlohmann::json& p = j["parameters"];
  if (!p.is_object())
    wang2009_json_fail(path, "parameters",
                       std::string("expected an object of name: value, got ") + p.type_name());
  for (auto it = p.begin(); it != p.end(); ++it)
    if (std::find(names.begin(), names.end(), it.key()) == names.end())
      wang2009_json_fail(path, "parameters." + it.key(),
                         "unknown parameter '" + it.key() + "' (the controller has " +
                             std::to_string(names.size()) + " parameters: " + names.front() +
                             ", ..., " + names.back() + ")");
  std::vector<double> out;
  out.reserve(names.size());
  for (const std::string& n : names) {
    if (!p.contains(n)) wang2009_json_fail(path, "parameters." + n, "missing");
    out.push_back(controller_json_number(path, p[n], "parameters." + n));
  }
  return out;
}

/// Writes j with "parameters" set to `values` by `names` (checked to match) to `path`.
inline void write_named_parameters(const std::string& path, nlohmann::json j,
                                   const std::vector<std::string>& names,
                                   const std::vector<double>& values, const char* what) {
  check_size(static_cast<std::ptrdiff_t>(values.size()), static_cast<std::ptrdiff_t>(names.size()),
             what);
  nlohmann::json p = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size(); ++i) p[names[i]] = values[i];
  j["parameters"] = p;
  std::ofstream out(path);
  if (!(out << j.dump(1) << "\n"))
    throw std::runtime_error("cannot write controller file '" + path + "'");
}

}  // namespace detail

/// The shape named by a saved controller (to build its model before reading its parameters).
inline std::string wang2009_saved_shape(const std::string& path) {
  const nlohmann::json j = detail::read_wang2009_json(path);
  if (!j.is_object() || !j.contains("shape") || !j["shape"].is_string())
    throw std::invalid_argument(path + ": field 'shape': expected a string, got " +
                                (j.is_object() && j.contains("shape")
                                     ? detail::wang2009_json_value(j["shape"])
                                     : std::string("nothing")));
  return j["shape"].get<std::string>();
}

/// Reads `path` for controller c (its parameter names). Throws std::invalid_argument naming the
/// file, the missing, unknown or malformed field and the bad value.
inline wang2009_saved_controller load_wang2009_controller(const std::string& path,
                                                          const wang2009_controller& c) {
  const nlohmann::json j = detail::read_wang2009_json(path);
  auto fail = [&](const std::string& field, const std::string& what) {
    detail::wang2009_json_fail(path, field, what);
  };
  auto number = [&](const nlohmann::json& v, const std::string& field) {
    return detail::controller_json_number(path, v, field);
  };
  if (!j.is_object()) fail("(top level)", std::string("expected an object, got ") + j.type_name());
  wang2009_saved_controller s;
  if (!j.contains("shape")) fail("shape", "missing");
  if (!j["shape"].is_string())
    fail("shape", "expected a string, got " + detail::wang2009_json_value(j["shape"]));
  s.shape = j["shape"].get<std::string>();
  auto optional_number = [&](const char* field, std::optional<double>& x) {
    if (j.contains(field) && !j[field].is_null()) x = number(j[field], field);
  };
  optional_number("target_speed", s.target_speed);
  optional_number("target_step_length", s.target_step_length);
  if (j.contains("cost")) s.cost = j["cost"].is_null() ? 0.0 : number(j["cost"], "cost");
  if (j.contains("info")) s.info = j["info"];
  s.parameters = detail::read_named_parameters(path, j, c.parameter_names());
  return s;
}

/// Writes s to `path` with the parameters named by c. Throws std::invalid_argument for a wrong
/// parameter count, std::runtime_error if the file cannot be written.
inline void save_wang2009_controller(const std::string& path, const wang2009_controller& c,
                                     const wang2009_saved_controller& s) {
  nlohmann::json j;
  j["paper"] = "Wang, Fleet & Hertzmann 2009";
  j["shape"] = s.shape;
  j["target_speed"] = s.target_speed ? nlohmann::json(*s.target_speed) : nlohmann::json(nullptr);
  j["target_step_length"] =
      s.target_step_length ? nlohmann::json(*s.target_step_length) : nlohmann::json(nullptr);
  j["cost"] = s.cost;
  if (!s.info.empty()) j["info"] = s.info;
  detail::write_named_parameters(path, std::move(j), c.parameter_names(), s.parameters,
                                 "wang2009 parameter vector");
}

}  // namespace gaitsynth
