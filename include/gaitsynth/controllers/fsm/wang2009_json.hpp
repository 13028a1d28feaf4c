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
/// controller replays bit for bit. Errors are std::invalid_argument naming the file and field.
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct wang2009_saved_controller {
  std::string shape = "stocky";
  std::optional<double> target_speed, target_step_length;
  double cost = 0.0;
  std::vector<double> parameters;  ///< in the controller's order
  nlohmann::json info = nlohmann::json::object();
};

/// The shape named by a saved controller (to build its model before reading its parameters).
inline std::string wang2009_saved_shape(const std::string& path) {
  std::ifstream in(path);
  check_argument(in.good(), "cannot open controller file '", path, "'");
  try {
    return nlohmann::json::parse(in).at("shape").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path + ": no shape (" + e.what() + ")");
  }
}

/// Reads `path` for controller c (its parameter names). Throws std::invalid_argument naming the
/// file and the missing or malformed field.
inline wang2009_saved_controller load_wang2009_controller(const std::string& path,
                                                          const wang2009_controller& c) {
  std::ifstream in(path);
  check_argument(in.good(), "cannot open controller file '", path, "'");
  wang2009_saved_controller s;
  std::string field = "(the JSON text)";
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    field = "shape";
    s.shape = j.at("shape").get<std::string>();
    field = "target_speed";
    if (j.contains(field) && !j[field].is_null()) s.target_speed = j[field].get<double>();
    field = "target_step_length";
    if (j.contains(field) && !j[field].is_null()) s.target_step_length = j[field].get<double>();
    field = "cost";
    if (j.contains(field)) s.cost = j[field].is_null() ? 0.0 : j[field].get<double>();
    field = "info";
    if (j.contains(field)) s.info = j[field];
    for (const std::string& n : c.parameter_names()) {
      field = "parameters." + n;
      s.parameters.push_back(j.at("parameters").at(n).get<double>());
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path + ": field '" + field + "': " + e.what());
  }
  return s;
}

/// Writes s to `path` with the parameters named by c. Throws std::invalid_argument for a wrong
/// parameter count, std::runtime_error if the file cannot be written.
inline void save_wang2009_controller(const std::string& path, const wang2009_controller& c,
                                     const wang2009_saved_controller& s) {
  const auto names = c.parameter_names();
  check_size(static_cast<std::ptrdiff_t>(s.parameters.size()),
             static_cast<std::ptrdiff_t>(names.size()), "wang2009 parameter vector");
  nlohmann::json j;
  j["paper"] = "Wang, Fleet & Hertzmann 2009";
  j["shape"] = s.shape;
  j["target_speed"] = s.target_speed ? nlohmann::json(*s.target_speed) : nlohmann::json(nullptr);
  j["target_step_length"] =
      s.target_step_length ? nlohmann::json(*s.target_step_length) : nlohmann::json(nullptr);
  j["cost"] = s.cost;
  nlohmann::json p = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size(); ++i) p[names[i]] = s.parameters[i];
  j["parameters"] = p;
  if (!s.info.empty()) j["info"] = s.info;
  std::ofstream out(path);
  if (!(out << j.dump(1) << "\n"))
    throw std::runtime_error("cannot write controller file '" + path + "'");
}

}  // namespace gaitsynth
