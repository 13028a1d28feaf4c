#pragma once
/// \file controllers/reflex/wang2012_json.hpp
/// Saving and loading an optimized wang2012_reflex_controller as JSON (needs nlohmann::json):
///
///     {
///       "paper": "Wang, Hamner, Delp & Koltun 2012",
///       "target_speed": 1.25,             // m/s of E_user
///       "cost": 412.0,                    // the objective over the optimized horizon
///       "parameters": {"p_GLU": 0.05, ...},   // all 122, by name
///       "info": { ... }                   // free-form (how it was made), kept as is
///     }
///
/// Doubles are written as the shortest decimals that read back exactly, so a saved controller
/// replays bit for bit. Errors are std::invalid_argument naming the file, the field and the bad
/// value (the helpers of wang2009_json.hpp).
#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"

namespace gaitsynth {

struct wang2012_saved_controller {
  double target_speed = 1.25;
  double cost = 0.0;
  std::vector<double> parameters;  ///< in wang2012_reflex_controller's order
  nlohmann::json info = nlohmann::json::object();
};

/// Reads `path`. Throws std::invalid_argument naming the file, the missing, unknown or malformed
/// field and the bad value.
inline wang2012_saved_controller load_wang2012_controller(const std::string& path) {
  const nlohmann::json j = detail::read_wang2009_json(path);
  auto fail = [&](const std::string& field, const std::string& what) {
    detail::wang2009_json_fail(path, field, what);
  };
  auto number = [&](const nlohmann::json& v, const std::string& field) {
    return detail::controller_json_number(path, v, field);
  };
  if (!j.is_object()) fail("(top level)", std::string("expected an object, got ") + j.type_name());
  wang2012_saved_controller s;
  if (!j.contains("target_speed")) fail("target_speed", "missing");
  s.target_speed = number(j["target_speed"], "target_speed");
  if (j.contains("cost")) s.cost = j["cost"].is_null() ? 0.0 : number(j["cost"], "cost");
  if (j.contains("info")) s.info = j["info"];
  s.parameters =
      detail::read_named_parameters(path, j, wang2012_reflex_controller::parameter_names());
  return s;
}

/// Writes s to `path`, the parameters by name. Throws std::invalid_argument for a wrong parameter
/// count, std::runtime_error if the file cannot be written.
inline void save_wang2012_controller(const std::string& path, const wang2012_saved_controller& s) {
  nlohmann::json j;
  j["paper"] = "Wang, Hamner, Delp & Koltun 2012";
  j["target_speed"] = s.target_speed;
  j["cost"] = s.cost;
  if (!s.info.empty()) j["info"] = s.info;
  detail::write_named_parameters(path, std::move(j), wang2012_reflex_controller::parameter_names(),
                                 s.parameters, "wang2012 parameter vector");
}

}  // namespace gaitsynth
