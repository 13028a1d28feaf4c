#pragma once
/// \file minimize.hpp
/// The driver loop for any `optimizer`: ask, evaluate the batch with an `evaluator`, tell; after
/// every iteration a CSV log row, a (throttled) compact progress line, a checkpoint every K
/// iterations, and a user callback that may stop the run. With `resume = true`, a run started
/// again with the same options continues from its last checkpoint, bit-identically.
#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"

namespace gaitsynth {

struct run_options {
  /// Stream for the compact progress line (nullptr: silent), e.g. &std::cerr.
  std::ostream* progress = nullptr;
  /// Minimum seconds between two progress lines (the first and last iterations always print).
  double progress_interval = 1.0;
  /// CSV log, one row per iteration (empty: none). Columns: see `csv_header`.
  std::filesystem::path log_file;
  /// Append the best point's coordinates (user units, one column per parameter name) to each row.
  bool log_parameters = false;
  /// Checkpoint file (empty: none), written every `checkpoint_every` iterations and at the end.
  std::filesystem::path checkpoint_file;
  std::int64_t checkpoint_every = 0;
  /// Load `checkpoint_file` first when it exists (and append to the log instead of truncating it).
  bool resume = false;
  /// Append to an existing log instead of truncating it (continuation stages after the first).
  bool append_log = false;
  /// Value of the `stage` column (continuation stages).
  int stage = 0;
};

struct optimization_result {
  Eigen::VectorXd x;                                        ///< best point seen, user coordinates
  double value = std::numeric_limits<double>::quiet_NaN();  ///< its objective value
  stop_criterion stopped = stop_criterion::none;            ///< why the run ended
  std::int64_t iterations = 0;
  std::int64_t evaluations = 0;
  std::int64_t non_finite = 0;  ///< non-finite objective values met (ranked worst)
  int restarts = 0;
  /// Each run of a restarting optimizer (cmaes_restarts::runs()): population, evaluations and its
  /// own stop criterion; empty for optimizers that do not restart.
  std::vector<run_record> runs;
  /// Wall time of this call (the log's elapsed_s counts on across calls).
  double elapsed_seconds = 0;
  bool resumed = false;  ///< started from a checkpoint
};

/// Callback type that does nothing.
struct no_callback {
  void operator()(const optimizer_status&) const {}
};

namespace detail {

inline std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

/// A process killed while writing a row leaves a line without its newline; a resumed run would
/// append its first row to it. Cut the file back to its last complete line.
inline void drop_torn_last_line(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.empty() || text.back() == '\n') return;
  const std::size_t keep = text.rfind('\n');
  std::filesystem::resize_file(file, keep == std::string::npos ? 0 : keep + 1);
}

/// The elapsed_s (13th column) of the last row of a convergence log, 0 when there is none (an
/// empty file, a header alone, an unreadable cell): a continued log counts on from it.
inline double last_logged_elapsed(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::size_t start = 0;
  for (int column = 0; column < 12 && start != std::string::npos; ++column) {
    start = last.find(',', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos || start >= last.size()) return 0.0;
  const char* first = last.c_str() + start;
  char* end = nullptr;
  const double t = std::strtod(first, &end);
  return end != first && std::isfinite(t) && t > 0.0 ? t : 0.0;
}

inline std::string format_seconds(double s) {
  char buf[32];
  if (!std::isfinite(s)) return "?";
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s / 60), static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s / 3600),
                  static_cast<int>(s / 60) % 60);
  return buf;
}

}  // namespace detail

/// Header of the CSV log (before any parameter columns).
inline constexpr const char* csv_header =
    "stage,restart,iteration,evaluations,best,iteration_best,iteration_median,iteration_worst,"
    "step_size,axis_ratio,batch_size,non_finite,elapsed_s";

/// The compact progress line, e.g.
/// `cmaes  it 120  ev 1200  best 1.234e-05  med 2.10e-05  step 3.2e-03  axis 12.3  1.2s  left
/// ~3.4s`
/// `elapsed` is this call's wall time and `fraction_at_start` the budget fraction it started
/// from (a resumed run's), so "left" extrapolates this call's own pace.
inline std::string progress_line(std::string_view name, const optimizer_status& s, double elapsed,
                                 double fraction_at_start = 0.0) {
  char buf[256];
  double left = std::numeric_limits<double>::quiet_NaN();
  const double done = s.budget_fraction - fraction_at_start;
  if (std::isfinite(done) && done > 0) left = elapsed * (1.0 - s.budget_fraction) / done;
  std::snprintf(buf, sizeof buf,
                "%.*s%s it %lld  ev %lld  best %.4e  med %.3e  step %.2e  axis %.3g  %s  left ~%s",
                static_cast<int>(name.size()), name.data(),
                s.restart > 0 ? (" r" + std::to_string(s.restart)).c_str() : "",
                static_cast<long long>(s.iteration), static_cast<long long>(s.evaluations),
                s.best_value, s.iteration_median, s.step_size, s.axis_ratio,
                detail::format_seconds(elapsed).c_str(), detail::format_seconds(left).c_str());
  std::string line = buf;
  if (s.non_finite > 0) line += "  nonfinite " + std::to_string(s.non_finite);
  if (s.stopped != stop_criterion::none) line += "  stop: " + std::string(to_string(s.stopped));
  return line;
}

/// Runs `opt` until it stops (or the callback returns false) and returns the best point.
/// `callback(const optimizer_status&)` is called after each iteration; if it returns bool, false
/// stops the run with stop_criterion::callback. Exceptions from the objective propagate (the last
/// checkpoint stays on disk, so the run can be resumed).
// clang-format off
template <class O, class F, class E, class Callback = no_callback>
  requires optimizer<std::remove_cvref_t<O>> &&
           evaluator<std::remove_cvref_t<E>, std::remove_reference_t<F>>
optimization_result minimize(O&& opt, F&& objective, E&& eval, const run_options& ro = {},
                             Callback&& callback = {}) {
  // clang-format on
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
  optimization_result result;
  check_argument(ro.checkpoint_every >= 0, "run_options::checkpoint_every must be >= 0, got ",
                 ro.checkpoint_every);
  check_argument(ro.progress_interval >= 0.0,
                 "run_options::progress_interval must be >= 0 s (inf: first and last lines only), "
                 "got ",
                 ro.progress_interval);

  if (ro.resume && !ro.checkpoint_file.empty() && std::filesystem::exists(ro.checkpoint_file)) {
    load_checkpoint(opt, ro.checkpoint_file);
    result.resumed = true;
  }
  const auto& space = opt.space();
  std::ofstream log;
  double log_elapsed_offset = 0.0;  // a continued log's elapsed_s counts on across calls
  if (!ro.log_file.empty()) {
    const bool continues =
        (result.resumed || ro.append_log) && std::filesystem::exists(ro.log_file);
    if (continues) detail::drop_torn_last_line(ro.log_file);
    const bool append = continues && std::filesystem::file_size(ro.log_file) > 0;
    if (append) log_elapsed_offset = detail::last_logged_elapsed(ro.log_file);
    log.open(ro.log_file, append ? std::ios::app : std::ios::trunc);
    if (!log) throw std::runtime_error("cannot write log file '" + ro.log_file.string() + "'");
    if (!append) {
      log << csv_header;
      if (ro.log_parameters)
        for (const auto& p : space.parameters()) log << ',' << detail::csv_escape(p.name);
      log << '\n';
    }
  }
  auto write_row = [&](const optimizer_status& s, double t) {
    if (!log.is_open()) return;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "%d,%d,%lld,%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%lld,%.3f", ro.stage,
                  s.restart, static_cast<long long>(s.iteration),
                  static_cast<long long>(s.evaluations), s.best_value, s.iteration_best,
                  s.iteration_median, s.iteration_worst, s.step_size, s.axis_ratio, s.batch_size,
                  static_cast<long long>(s.non_finite), log_elapsed_offset + t);
    log << buf;
    if (ro.log_parameters) {
      const Eigen::VectorXd& x = opt.best_x();
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        std::snprintf(buf, sizeof buf, ",%.17g", x[i]);
        log << buf;
      }
    }
    log << '\n';
  };

  std::vector<double> values;
  double last_print = -1e300;
  const double fraction_at_start =
      std::isfinite(opt.status().budget_fraction) ? opt.status().budget_fraction : 0.0;
  bool by_callback = false;
  optimizer_status status = opt.status();
  while (opt.stopped() == stop_criterion::none) {
    const std::vector<Eigen::VectorXd>& xs = opt.ask();
    values.assign(xs.size(), 0.0);
    eval.evaluate(objective, std::span<const Eigen::VectorXd>(xs), std::span<double>(values));
    opt.tell(std::span<const double>(values));
    status = opt.status();
    const double t = elapsed();
    write_row(status, t);
    if (ro.checkpoint_every > 0 && !ro.checkpoint_file.empty() &&
        status.iteration % ro.checkpoint_every == 0) {
      // The log's rows up to the checkpoint reach the disk first, so a run killed after it
      // and resumed keeps every row (the ones after the checkpoint are repeated).
      if (log.is_open()) log.flush();
      save_checkpoint(opt, ro.checkpoint_file);
    }
    if constexpr (std::is_invocable_r_v<bool, Callback&, const optimizer_status&> &&
                  !std::is_void_v<std::invoke_result_t<Callback&, const optimizer_status&>>) {
      if (!callback(status)) by_callback = true;
    } else {
      callback(status);
    }
    if (by_callback) status.stopped = stop_criterion::callback;
    if (ro.progress && (t - last_print >= ro.progress_interval || status.iteration == 1 ||
                        status.stopped != stop_criterion::none || by_callback)) {
      *ro.progress << progress_line(opt.name(), status, t, fraction_at_start) << '\n';
      last_print = t;
    }
    if (by_callback) break;
  }
  if (!ro.checkpoint_file.empty() && ro.checkpoint_every > 0)
    save_checkpoint(opt, ro.checkpoint_file);

  result.x = opt.best_x();
  result.value = opt.best_value();
  result.stopped = by_callback ? stop_criterion::callback : opt.stopped();
  result.iterations = status.iteration;
  result.evaluations = status.evaluations;
  result.non_finite = status.non_finite;
  result.restarts = status.restart;
  if constexpr (requires { opt.runs(); }) result.runs = opt.runs();
  result.elapsed_seconds = elapsed();
  return result;
}

/// minimize with the serial evaluator.
// clang-format off
template <class O, class F, class Callback = no_callback>
  requires optimizer<std::remove_cvref_t<O>> && objective_function<std::remove_reference_t<F>>
optimization_result minimize(O&& opt, F&& objective, const run_options& ro = {},
                             Callback&& callback = {}) {
  // clang-format on
  serial_evaluator e;
  return minimize(std::forward<O>(opt), std::forward<F>(objective), e, ro,
                  std::forward<Callback>(callback));
}

}  // namespace gaitsynth
