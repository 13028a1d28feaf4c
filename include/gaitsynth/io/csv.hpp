#pragma once
/// \file io/csv.hpp
/// Writes a recorded trajectory (rollout/trajectory.hpp) as CSV: one row per frame, and a header
/// that names every column with its unit in brackets, e.g. "t [s]", "q_lknee [rad]",
/// "v_root_x [m/s]", "tau_lknee [N m]", "lfoot_qw [1]", "lheel_fz [N]". Units follow from the
/// coordinate names (root_x/y/z translate, root_qw..qz are quaternion components, everything else
/// is an angle). Objective terms keep their own bracketed unit if their name has one ("[1]" else).
/// Numbers are written with max_digits10 so that they read back exactly.
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

namespace detail {
inline bool is_root_translation(const std::string& n) {
  return n == "root_x" || n == "root_y" || n == "root_z";
}
inline bool is_quaternion_component(const std::string& n) {
  return n.rfind("root_q", 0) == 0;
}
}  // namespace detail

/// The header columns of write_csv for trajectory tr, each "name [unit]".
inline std::vector<std::string> csv_columns(const trajectory& tr) {
  std::vector<std::string> c;
  c.push_back("t [s]");
  for (const auto& n : tr.q_names)
    c.push_back("q_" + n +
                (detail::is_root_translation(n)       ? " [m]"
                 : detail::is_quaternion_component(n) ? " [1]"
                                                      : " [rad]"));
  for (const auto& n : tr.v_names)
    c.push_back("v_" + n + (detail::is_root_translation(n) ? " [m/s]" : " [rad/s]"));
  for (const auto& n : tr.v_names)
    c.push_back("tau_" + n + (detail::is_root_translation(n) ? " [N]" : " [N m]"));
  for (const char* a : {"x", "y", "z"}) c.push_back(std::string("com_") + a + " [m]");
  for (const auto& b : tr.body_names) {
    for (const char* a : {"x", "y", "z"}) c.push_back(b + "_" + a + " [m]");
    for (const char* a : {"qw", "qx", "qy", "qz"}) c.push_back(b + "_" + a + " [1]");
  }
  for (const auto& n : tr.contact_names) {
    for (const char* a : {"x", "y", "z"}) c.push_back(n + "_" + a + " [m]");
    for (const char* a : {"fx", "fy", "fz"}) c.push_back(n + "_" + a + " [N]");
    c.push_back(n + "_active [1]");
  }
  c.push_back("push_body [index]");
  for (const char* a : {"fx", "fy", "fz"}) c.push_back(std::string("push_") + a + " [N]");
  for (const auto& n : tr.objective_term_names)
    c.push_back("objective_" + n + (n.find('[') == std::string::npos ? " [1]" : ""));
  c.push_back("controller_state [index]");
  return c;
}

/// Writes tr as CSV (header + one row per frame) to os. Throws std::invalid_argument if a frame's
/// sizes disagree with the trajectory's names.
inline void write_csv(std::ostream& os, const trajectory& tr) {
  const auto cols = csv_columns(tr);
  for (std::size_t i = 0; i < cols.size(); ++i) os << (i ? "," : "") << cols[i];
  os << '\n';
  const auto old_precision = os.precision(std::numeric_limits<double>::max_digits10);
  for (std::size_t fi = 0; fi < tr.frames.size(); ++fi) {
    const trajectory_frame& f = tr.frames[fi];
    auto bad = [&](const char* what) {
      return std::invalid_argument("write_csv: frame " + std::to_string(fi) + " has a " + what +
                                   " of the wrong size for trajectory '" + tr.model_name + "'");
    };
    if (static_cast<std::size_t>(f.q.size()) != tr.q_names.size()) throw bad("q");
    if (static_cast<std::size_t>(f.v.size()) != tr.v_names.size()) throw bad("v");
    if (static_cast<std::size_t>(f.tau.size()) != tr.v_names.size()) throw bad("tau");
    if (f.body_position.size() != tr.body_names.size() ||
        f.body_orientation.size() != tr.body_names.size())
      throw bad("body pose list");
    if (f.contact_position.size() != tr.contact_names.size() ||
        f.contact_force.size() != tr.contact_names.size() ||
        f.contact_active.size() != tr.contact_names.size())
      throw bad("contact list");
    if (f.objective_terms.size() != tr.objective_term_names.size()) throw bad("objective terms");
    os << f.t;
    for (Eigen::Index i = 0; i < f.q.size(); ++i) os << ',' << f.q[i];
    for (Eigen::Index i = 0; i < f.v.size(); ++i) os << ',' << f.v[i];
    for (Eigen::Index i = 0; i < f.tau.size(); ++i) os << ',' << f.tau[i];
    os << ',' << f.com.x() << ',' << f.com.y() << ',' << f.com.z();
    for (std::size_t b = 0; b < tr.body_names.size(); ++b) {
      const auto& p = f.body_position[b];
      const auto& q = f.body_orientation[b];
      os << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << q.w() << ',' << q.x() << ','
         << q.y() << ',' << q.z();
    }
    for (std::size_t c = 0; c < tr.contact_names.size(); ++c) {
      const auto& p = f.contact_position[c];
      const auto& F = f.contact_force[c];
      os << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << F.x() << ',' << F.y() << ','
         << F.z() << ',' << static_cast<int>(f.contact_active[c]);
    }
    Eigen::Vector3d push_force = Eigen::Vector3d::Zero();
    for (const auto& p : f.pushes) push_force += p.second;
    os << ',' << (f.pushes.empty() ? -1 : f.pushes.front().first) << ',' << push_force.x() << ','
       << push_force.y() << ',' << push_force.z();
    for (double v : f.objective_terms) os << ',' << v;
    os << ',' << f.controller_state << '\n';
  }
  os.precision(old_precision);
}

/// Writes tr as CSV to the file `path`. Throws std::runtime_error if the file cannot be written.
inline void save_csv(const std::string& path, const trajectory& tr) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("save_csv: cannot open '" + path + "' for writing");
  write_csv(f, tr);
  if (!f) throw std::runtime_error("save_csv: writing '" + path + "' failed");
}

}  // namespace gaitsynth
