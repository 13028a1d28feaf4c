#pragma once
// The examples' command lines, on CLI11 (Debian's libcli11-dev): typed values with ranges
// ("--threads -1" and "--check-seconds 5x" are refused), --help that exits 0 and lists every flag
// with its default, unknown flags refused with the closest name, the viewer flags as one option
// group, and the run folder of an optimizing example (--out DIR, default
// out/<example>/<UTC time>/) with the effective options as JSON.
//
//   CLI::App app{"what the example does"};
//   example_cli::add_threads(app, threads);
//   app.add_option("--check-seconds", seconds, "...")->check(example_cli::in_range(0.1, 1e4));
//   example_cli::add_viewer_flags(app, viz);
//   example_cli::parse(app, argc, argv);   // --help: exit 0; a bad command line: message, exit 2
//
// A bad command line exits with status 2, as POSIX tools do; a bad input found later (a file, a
// value that depends on another) is an exception the example reports with status 1.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "gaitsynth/io/viewer_outputs.hpp"

#ifdef GAITSYNTH_REVISION_LINKED
namespace gaitsynth_examples {
/// The source tree's git revision when this program was built ("-dirty": with uncommitted changes
/// to tracked files); generated at every build by cmake/git_revision.cmake.
const char* git_revision();
}  // namespace gaitsynth_examples
#endif

namespace example_cli {

/// A value read whole by `read` (std::stod, std::stoll) and within [lo, hi]; `kind` names what it
/// must be ("a number", "a whole number") when it is not one.
template <class T, class Read>
CLI::Validator read_in_range(T lo, T hi, const std::string& description, const std::string& kind,
                             Read read) {
  return CLI::Validator(
      [lo, hi, kind, read](std::string& s) -> std::string {
        T v{};
        std::size_t used = 0;
        try {
          v = read(s, &used);
        } catch (...) {
          used = 0;
        }
        if (used != s.size() || s.empty()) return "'" + s + "' is not " + kind;
        if (!(v >= lo && v <= hi)) {  // (NaN fails too)
          std::ostringstream m;
          m << "must be in [" << lo << ", " << hi << "], got " << s;
          return m.str();
        }
        return {};
      },
      description);
}

/// A number in [lo, hi] (finite); the message names the flag, the range and the value.
inline CLI::Validator in_range(double lo, double hi) {
  std::ostringstream d;
  d << "in [" << lo << ", " << hi << "]";
  return read_in_range(lo, hi, d.str(), "a number",
                       [](const std::string& s, std::size_t* used) { return std::stod(s, used); });
}

/// A whole number in [lo, hi]: "1.5", "-1" for a count or "3x" are refused by name.
inline CLI::Validator integer_in(long long lo, long long hi) {
  std::ostringstream d;
  d << "integer in [" << lo << ", " << hi << "]";
  return read_in_range(lo, hi, d.str(), "a whole number",
                       [](const std::string& s, std::size_t* used) { return std::stoll(s, used); });
}

/// NAME=NUMBER (NAME=LO:HI with `pair`), as --weight and --bound take them.
inline CLI::Validator name_equals_number(bool pair = false) {
  return CLI::Validator(
      [pair](std::string& s) -> std::string {
        const std::size_t eq = s.find('=');
        const std::string form = pair ? "NAME=LO:HI" : "NAME=VALUE";
        if (eq == std::string::npos || eq == 0) return "wants " + form + ", got '" + s + "'";
        auto number = [](const std::string& t) {
          std::size_t used = 0;
          try {
            const double v = std::stod(t, &used);
            return used == t.size() && std::isfinite(v);
          } catch (...) {
            return false;
          }
        };
        const std::string rest = s.substr(eq + 1);
        if (!pair) return number(rest) ? "" : "wants " + form + " with a number, got '" + s + "'";
        const std::size_t colon = rest.find(':');
        if (colon == std::string::npos || !number(rest.substr(0, colon)) ||
            !number(rest.substr(colon + 1)))
          return "wants " + form + " with two numbers, got '" + s + "'";
        if (std::stod(rest.substr(0, colon)) >= std::stod(rest.substr(colon + 1)))
          return "wants LO < HI, got '" + s + "'";
        return {};
      },
      pair ? "NAME=LO:HI" : "NAME=VALUE");
}

/// Edit distance, for "did you mean".
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

/// Every option of app and of its option groups.
inline std::vector<const CLI::Option*> all_options(const CLI::App& app) {
  std::vector<const CLI::Option*> all = app.get_options();
  for (const CLI::App* group : app.get_subcommands([](const CLI::App*) { return true; }))
    for (const CLI::Option* o : group->get_options()) all.push_back(o);
  return all;
}

/// The long flag name closest to `given` ("--thread" -> "--threads").
inline std::string closest_flag(const CLI::App& app, const std::string& given) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const CLI::Option* o : all_options(app))
    for (const std::string& n : o->get_lnames()) {
      const std::size_t d = edit_distance(given, "--" + n);
      if (d < best_d) best_d = d, best = "--" + n;
    }
  return best;
}

/// Parses argv. --help prints every flag with its default and exits 0; a bad command line prints
/// what is wrong (an unknown flag with the closest name) and exits 2.
inline void parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::exit(app.exit(e));
  } catch (const CLI::ExtrasError&) {
    std::string message;
    for (const std::string& extra : app.remaining()) {
      if (extra.rfind("-", 0) == 0) {
        message = "unknown option '" + extra + "'";
        const std::string flag = extra.substr(0, extra.find('='));
        const std::string near = closest_flag(app, flag);
        if (!near.empty() && edit_distance(flag, near) <= std::max<std::size_t>(2, flag.size() / 3))
          message += "; did you mean '" + near + "'?";
        break;
      }
    }
    if (message.empty()) message = "unexpected argument '" + app.remaining().front() + "'";
    std::cerr << app.get_name() << ": " << message << " (--help lists the options)\n";
    std::exit(2);
  } catch (const CLI::ParseError& e) {
    std::cerr << app.get_name() << ": " << e.what() << " (--help lists the options)\n";
    std::exit(2);
  }
}

/// --threads N: evaluation threads, 0 (the default) = every core. Call resolve_threads after
/// parsing.
inline CLI::Option* add_threads(CLI::App& app, unsigned& threads) {
  return app.add_option("--threads", threads, "evaluation threads, 0 = every core")
      ->check(integer_in(0, 4096));
}
inline unsigned resolve_threads(unsigned threads) {
  return threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// --seed N: the seed of everything random in the run. `max`: the largest seed the example's
/// generator takes whole (4294967295 for a std::mt19937).
inline CLI::Option* add_seed(CLI::App& app, unsigned long long& seed,
                             long long max = std::numeric_limits<long long>::max()) {
  return app.add_option("--seed", seed, "random seed")->check(integer_in(0, max));
}

/// --push-direction-step, --push-period, --push-phase and --push-directions: the schedule of a
/// robust optimization's pushed rollouts (synthesis/robust_variants.hpp), as wang2009_walk and
/// wang2012_walk take it. direction_step -1 stands for the number of pushed rollouts.
inline void add_push_schedule_flags(CLI::App& app, int& direction_step, double& period,
                                    std::string& phase, std::vector<int>& directions) {
  app.add_option("--push-direction-step", direction_step,
                 "directions each later push of a pushed rollout turns on (-1: K, so K = 3 "
                 "rollouts push all eight; 0: each rollout pushes its own direction every time, "
                 "as Table 1's protocol does)")
      ->check(integer_in(-1, 7));
  app.add_option("--push-period", period,
                 "s between the starts of a pushed rollout's pushes (the first at 2 s; Table 1's "
                 "protocol: 4)")
      ->check(in_range(0.5, 1000.0));
  app.add_option("--push-phase", phase,
                 "fixed: a pushed rollout's pushes start at 2 s; random: each pushed rollout's "
                 "pushes move by its own phase in [0, push period), drawn anew every iteration")
      ->check(CLI::IsMember({"fixed", "random"}));
  app.add_option(
         "--push-directions", directions,
         "the first direction of each pushed rollout, as indices 0-7 into Table 1's "
         "(1,0), (1,1), (0,1), (-1,1), (-1,0), (-1,-1), (0,-1), (1,-1), one per "
         "--robust-pushes (ours: a direction listed twice weighs twice); default 0, 1, 2, ...")
      ->delimiter(',')
      ->check(integer_in(0, 7));
}

/// --keep-means: every checkpoint also keeps CMA's mean as STEM.meanN.json (kept_mean_suffix),
/// beside STEM.mean.json, which each checkpoint overwrites: a stage's means can then be compared
/// after the run (a run's best mean need not be its last).
inline void add_keep_means(CLI::App& app, bool& keep) {
  app.add_flag("--keep-means", keep,
               "also keep CMA's mean at every checkpoint as STEM.meanN.json (N: the iteration; "
               "STEM.mean.json is overwritten at each)");
}
inline std::string kept_mean_suffix(long long iteration) {
  return ".mean" + std::to_string(iteration) + ".json";
}

/// Throws std::invalid_argument unless --push-directions is empty or names one direction per
/// pushed rollout.
inline void check_push_directions(const std::vector<int>& directions, int robust_pushes) {
  if (!directions.empty() && std::ssize(directions) != robust_pushes)
    throw std::invalid_argument("--push-directions: " + std::to_string(directions.size()) +
                                " given, --robust-pushes " + std::to_string(robust_pushes) +
                                ": give one direction per pushed rollout");
}

/// The viewer flags (io/viewer_outputs.hpp, docs/viewer.md) as one option group.
inline CLI::Option_group* add_viewer_flags(CLI::App& app, gaitsynth::viz_outputs& v,
                                           const std::string& of = "the check rollout") {
  CLI::Option_group* g = app.add_option_group("viewer", "files that show " + of);
  g->add_option("--html", v.html, "self-contained HTML player");
  g->add_option("--filmstrip", v.filmstrip_svg, "SVG strobe filmstrip, side view");
  g->add_option("--filmstrip-front", v.filmstrip_front_svg, "SVG strobe filmstrip, front view");
  g->add_option("--gait-svg", v.gait_svg, "SVG gait-cycle plots");
  g->add_option("--bvh", v.bvh, "BVH motion (centimetres, Y up)");
  g->add_option("--csv", v.trajectory_csv, "trajectory CSV");
  g->add_option("--mjcf-replay", v.mjcf_replay, "MJCF model with one keyframe per frame");
  return g;
}

/// UTC now as 20261203T054512Z (a folder name that sorts by time).
inline std::string utc_stamp() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char s[32];
  std::strftime(s, sizeof s, "%Y%m%dT%H%M%SZ", &tm);
  return s;
}

/// The run folder: `out` when given, else out/<example>/<UTC time>/ (created).
inline std::filesystem::path run_folder(const std::string& example, const std::string& out) {
  std::filesystem::path dir = out.empty() ? std::filesystem::path("out") / example / utc_stamp()
                                          : std::filesystem::path(out);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Every option's effective value (given or default) by long name.
inline nlohmann::json effective_options(const CLI::App& app) {
  nlohmann::json o = nlohmann::json::object();
  for (const CLI::Option* opt : all_options(app)) {
    if (opt->get_lnames().empty()) continue;
    const std::string name = opt->get_lnames().front();
    if (name == "help") continue;
    if (opt->get_expected_max() == 0)  // a flag
      o[name] = opt->count() > 0;
    else if (opt->get_items_expected_max() > 1)  // repeatable: every value given
      o[name] = opt->results();
    else if (opt->count() > 0)
      o[name] = opt->results().empty() ? "" : opt->results().back();
    else
      o[name] = opt->get_default_str();
  }
  return o;
}

/// The build this program came from: compiler, flags, git revision (at build time; a program
/// compiled outside CMake has none).
inline nlohmann::json build_info() {
  nlohmann::json b;
#ifdef GAITSYNTH_REVISION_LINKED
  b["git_revision"] = ::gaitsynth_examples::git_revision();
#endif
#ifdef GAITSYNTH_BUILD_FLAGS
  b["flags"] = GAITSYNTH_BUILD_FLAGS;
#endif
  b["compiler"] = __VERSION__;
#ifdef NDEBUG
  b["ndebug"] = true;
#else
  b["ndebug"] = false;
#endif
  return b;
}

/// Writes DIR/options.json: the command, every option's effective value (effective_options), the
/// time and the build.
inline void write_options(const std::string& command, const nlohmann::json& options,
                          const std::filesystem::path& dir) {
  nlohmann::json j;
  j["command"] = command;
  j["started_utc"] = utc_stamp();
  j["options"] = options;
  j["build"] = build_info();
  const std::filesystem::path file = dir / "options.json";
  std::ofstream out(file);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

/// The run's one-line JSON summary: on stdout, and as DIR/summary.json in the run folder.
template <class Json>  // nlohmann::json or nlohmann::ordered_json
void report_summary(const Json& summary, const std::filesystem::path& dir) {
  std::cout << summary.dump() << std::endl;
  if (dir.empty()) return;
  std::ofstream(dir / "summary.json") << summary.dump(2) << "\n";
}

/// --resume DIR: the options recorded in DIR/options.json as a command line, but those named in
/// `skip`, to be parsed again so the run continues exactly as it started.
inline std::vector<std::string> recorded_arguments(const std::filesystem::path& dir,
                                                   const std::vector<std::string>& skip) {
  const std::filesystem::path file = dir / "options.json";
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error("--resume: no run folder at " + dir.string() + " (no " +
                             file.string() + ")");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  if (!j.contains("options") || !j["options"].is_object())
    throw std::runtime_error(file.string() + ": no 'options' object");
  std::vector<std::string> args;
  for (const auto& [name, value] : j["options"].items()) {
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    if (value.is_boolean()) {
      if (value.get<bool>()) args.push_back("--" + name);
    } else if (value.is_array()) {
      for (const auto& v : value) args.insert(args.end(), {"--" + name, v.get<std::string>()});
    } else if (value.is_string()) {
      if (!value.get<std::string>().empty())
        args.insert(args.end(), {"--" + name, value.get<std::string>()});
    } else {
      throw std::runtime_error(file.string() + ": option '" + name +
                               "' is not a string, a list "
                               "or a flag");
    }
  }
  return args;
}

/// --resume DIR: parses the options recorded in DIR/options.json again with `app` (which parsed
/// the resume command), so the run goes on exactly as it started. The options named in `also`
/// (those that do not change the result, such as threads) may be given with --resume and keep
/// the values given now. Those named in `continuation` (a change of the problem that the
/// optimizer's state carries over, such as a penalty weight) replace the recorded value when
/// given and keep it otherwise; the caller records the change (record_continuation). Any other
/// option given is refused. Returns the continuation options that were given.
inline std::vector<std::string> reparse_recorded(
    CLI::App& app, const char* argv0, const std::string& dir, const std::vector<std::string>& also,
    const std::vector<std::string>& continuation = {}) {
  std::vector<std::string> args{argv0}, given;
  auto named = [](const std::vector<std::string>& v, const std::string& n) {
    return std::find(v.begin(), v.end(), n) != v.end();
  };
  for (const CLI::Option* o : all_options(app)) {
    const std::string n = o->get_lnames().empty() ? "" : o->get_lnames().front();
    if (o->count() == 0 || n == "resume") continue;
    if (!named(also, n) && !named(continuation, n)) {
      std::string allowed;
      for (const auto* list : {&also, &continuation})
        for (const std::string& a : *list) allowed += (allowed.empty() ? "--" : ", --") + a;
      throw std::invalid_argument("--resume " + dir + ": the run goes on with the options it " +
                                  "recorded; --" + n + " cannot be given with it (only " + allowed +
                                  ")");
    }
    if (named(continuation, n)) given.push_back(n);
    if (o->get_expected_max() == 0)
      args.push_back("--" + n);
    else
      for (const std::string& r : o->results()) args.insert(args.end(), {"--" + n, r});
  }
  std::vector<std::string> skip = also;
  skip.insert(skip.end(), given.begin(), given.end());
  skip.insert(skip.end(), {"out", "resume"});
  for (const std::string& a : recorded_arguments(dir, skip)) args.push_back(a);
  std::vector<char*> av;
  for (std::string& a : args) av.push_back(a.data());
  app.clear();
  parse(app, static_cast<int>(av.size()), av.data());
  return given;
}

/// A continuation of the run in DIR (reparse_recorded's `continuation` options given with
/// --resume): DIR/options.json's options take the new values `changed` (name -> value as
/// written), so later resumes keep them, and its "continuations" list gains an entry with the
/// command, the time, the iteration the optimizer's state resumed at, and the changed values.
inline void record_continuation(const std::filesystem::path& dir, const std::string& command,
                                long long iteration,
                                const std::map<std::string, std::string>& changed) {
  const std::filesystem::path file = dir / "options.json";
  nlohmann::json j;
  {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    in >> j;
  }
  nlohmann::json entry;
  entry["command"] = command;
  entry["resumed_utc"] = utc_stamp();
  entry["from_iteration"] = iteration;
  for (const auto& [name, value] : changed) {
    j["options"][name] = value;
    entry["options"][name] = value;
  }
  entry["build"] = build_info();
  j["continuations"].push_back(entry);
  std::ofstream out(file);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace example_cli
