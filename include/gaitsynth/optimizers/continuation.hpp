#pragma once
/// \file continuation.hpp
/// Continuation: a sequence of optimization problems, each started from the previous result.
/// Sharon & van de Panne 2005 (Sec. V-C, "bootstrapping") optimize over episodes whose simulation
/// horizon grows from 0.2 s to 2 s; Wang 2009 walks up slopes of 3 to 12 degrees; Wang 2012 runs
/// at speeds raised in 0.5 m/s steps. All are `continuation(stages, x0, make_optimizer,
/// make_objective, ...)` with any optimizer (CMA-ES, its restarts, SDS).
///
/// Checkpointing: with `run_options::checkpoint_file = P`, stage k checkpoints to `P.stage<k>` and
/// the results of finished stages are kept in `P`; with `resume = true` a restarted program skips
/// the finished stages and resumes the current one from its checkpoint.
#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/minimize.hpp"

namespace gaitsynth {

struct continuation_result {
  std::vector<optimization_result> stages;  ///< one per stage, in order
  Eigen::VectorXd x;                        ///< best point of the last stage (user coordinates)
  double value = std::numeric_limits<double>::quiet_NaN();  ///< its value (last stage's objective)
};

namespace detail {

inline void write_stage_results(const std::filesystem::path& path,
                                const std::vector<optimization_result>& rs) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream os(tmp, std::ios::trunc);
    if (!os) throw std::runtime_error("cannot write '" + tmp.string() + "'");
    checkpoint_writer w(os);
    w.text("magic", checkpoint_magic);
    w.text("optimizer", "continuation");
    w.integer("stages_done", static_cast<std::int64_t>(rs.size()));
    for (const auto& r : rs) {
      w.vector("x", r.x);
      w.real("value", r.value);
      w.integer("stopped", static_cast<std::int64_t>(r.stopped));
      w.integer("iterations", r.iterations);
      w.integer("evaluations", r.evaluations);
      w.integer("non_finite", r.non_finite);
      w.integer("restarts", r.restarts);
    }
  }
  std::filesystem::rename(tmp, path);
}

inline std::vector<optimization_result> read_stage_results(const std::filesystem::path& path) {
  std::ifstream is(path);
  if (!is) throw std::runtime_error("cannot read '" + path.string() + "'");
  checkpoint_reader r(is, path.string());
  r.require_text("magic", checkpoint_magic);
  r.require_text("optimizer", "continuation");
  const auto n = r.integer("stages_done");
  if (n < 0) r.error("expected a non-negative count of stages, got " + std::to_string(n));
  // One stage at a time: a corrupt count fails as a short file rather than allocating first.
  std::vector<optimization_result> rs;
  for (std::int64_t k = 0; k < n; ++k) {
    optimization_result& res = rs.emplace_back();
    res.x = r.vector("x");
    res.value = r.real("value");
    res.stopped = static_cast<stop_criterion>(r.integer("stopped"));
    res.iterations = r.integer("iterations");
    res.evaluations = r.integer("evaluations");
    res.non_finite = r.integer("non_finite");
    res.restarts = static_cast<int>(r.integer("restarts"));
    res.resumed = true;
  }
  return rs;
}

}  // namespace detail

/// Runs `num_stages` optimizations. Stage k uses the objective `make_objective(k)` and the
/// optimizer `make_optimizer(k, start)`, where `start` (user coordinates) is x0 for k = 0 and the
/// best point of stage k-1 afterwards (e.g. `cmaes(space, opts_with_x0 = start)`). The CSV log, if
/// any, gets every stage with its `stage` column. The callback is passed on to each stage.
template <class MakeOptimizer, class MakeObjective, class E, class Callback = no_callback>
continuation_result continuation(std::size_t num_stages, const Eigen::VectorXd& x0,
                                 MakeOptimizer&& make_optimizer, MakeObjective&& make_objective,
                                 E&& eval, const run_options& ro = {}, Callback&& callback = {}) {
  check_argument(num_stages > 0, "continuation: num_stages must be > 0, got ", num_stages);
  check_finite(x0, "continuation x0");
  continuation_result out;
  const bool ckpt = !ro.checkpoint_file.empty();
  if (ckpt && ro.resume && std::filesystem::exists(ro.checkpoint_file))
    out.stages = detail::read_stage_results(ro.checkpoint_file);
  check_argument(out.stages.size() <= num_stages, "continuation: checkpoint has ",
                 out.stages.size(), " finished stages, more than num_stages = ", num_stages);
  Eigen::VectorXd start = out.stages.empty() ? x0 : out.stages.back().x;
  for (std::size_t k = out.stages.size(); k < num_stages; ++k) {
    auto opt = make_optimizer(k, static_cast<const Eigen::VectorXd&>(start));
    static_assert(optimizer<decltype(opt)>, "make_optimizer must return an optimizer");
    auto objective = make_objective(k);
    run_options stage_ro = ro;
    stage_ro.stage = static_cast<int>(k);
    stage_ro.append_log = ro.append_log || k > 0 || (ro.resume && !out.stages.empty());
    if (ckpt) {
      stage_ro.checkpoint_file = ro.checkpoint_file;
      stage_ro.checkpoint_file += ".stage" + std::to_string(k);
    }
    optimization_result r = minimize(opt, objective, eval, stage_ro, callback);
    out.stages.push_back(r);
    if (ckpt) detail::write_stage_results(ro.checkpoint_file, out.stages);
    start = r.x;
    if (r.stopped == stop_criterion::callback) break;
  }
  out.x = out.stages.back().x;
  out.value = out.stages.back().value;
  return out;
}

}  // namespace gaitsynth
