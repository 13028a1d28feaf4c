// The bad-input corpus tests/bad_inputs/ (its README.md lists every file): each file, a small valid
// file of one loader's format with one defect, must be refused with a std::exception whose what()
// names the file, the line, field or key of the defect and the bad value, and a failed
// load_checkpoint must leave the optimizer exactly as it was.
//
// Nothing half-loaded: load_keyframes, load_nearest_neighbor, load_wang2009_controller,
// load_wang2012_controller, load_trajectory_csv and load_normative_gait return their result by
// value, so a throw leaves the caller with nothing; only load_checkpoint loads into an existing
// object, checked below.
#include <catch2/catch.hpp>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#include "gaitsynth/io/normative_gait.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/optimizers/optimizers.hpp"

using namespace gaitsynth;
namespace fs = std::filesystem;

namespace {

const fs::path corpus = fs::path(GAITSYNTH_SOURCE_DIR) / "tests" / "bad_inputs";

/// One corpus file and the substrings its loader's message must contain: the file name, the
/// line / field / key, the bad value (where there is one).
struct bad_file {
  std::string path;  ///< relative to tests/bad_inputs
  std::vector<std::string> expected;
};

// clang-format off
const std::vector<bad_file> table = {
  // keyframes JSON (load_keyframes, model sharon2005_human7)
  {"keyframes/truncated.json", {"truncated.json", "malformed JSON", "line 19, column 16", "unexpected end of input"}},
  {"keyframes/wrong_type_string.json", {"wrong_type_string.json", "end_time", "\"0.27\"", "string"}},
  {"keyframes/wrong_type_object.json", {"wrong_type_object.json", "keyframes", "got object"}},
  {"keyframes/nan.json", {"nan.json", "keyframes[1].pose.lknee", "\"NaN\""}},
  {"keyframes/inf.json", {"inf.json", "line 32, column 17", "1e999", "too large"}},
  {"keyframes/wrong_dof_count.json", {"wrong_dof_count.json", "keyframes[1].pose", "nq = 9", "got 8"}},
  {"keyframes/unknown_joint.json", {"unknown_joint.json", "keyframes[1].pose.lkne", "'lkne'"}},
  {"keyframes/duplicate_key.json", {"duplicate_key.json", "line 34, column 9", "duplicate key \"rhip\"", "first at line 32"}},
  {"keyframes/huge_number.json", {"huge_number.json", "line 29, column 19", "1000000000000000", "400 characters", "too large"}},
  {"keyframes/empty.json", {"empty.json: malformed JSON", "line 1, column 1", "unexpected end of input"}},
  {"keyframes/binary_garbage.json", {"binary_garbage.json", "line 1, column 1", "invalid literal; last read"}},
  {"keyframes/deeply_nested.json", {"deeply_nested.json", "line 5, column 267", "deeper than 256"}},

  // nearest-neighbor controller JSON (load_nearest_neighbor, model sharon2005_human7)
  {"nearest_neighbor/truncated.json", {"truncated.json", "malformed JSON", "line 69, column 35", "unexpected end of input"}},
  {"nearest_neighbor/wrong_type_string.json", {"wrong_type_string.json", "options.torso_kp", "\"1000\""}},
  {"nearest_neighbor/wrong_type_object.json", {"wrong_type_object.json", "options.kp", "got object"}},
  {"nearest_neighbor/nan.json", {"nan.json", "nodes[0].output.lknee", "\"NaN\""}},
  {"nearest_neighbor/inf.json", {"inf.json", "line 69, column 17", "1e999", "too large"}},
  {"nearest_neighbor/wrong_vector_size.json", {"wrong_vector_size.json", "options.kp", "expected 6 gains", "got 5"}},
  {"nearest_neighbor/unknown_joint.json", {"unknown_joint.json", "nodes[0].output.lkne", "'lkne'"}},
  {"nearest_neighbor/unknown_option.json", {"unknown_option.json", "options.torso_kdd", "'torso_kdd'"}},
  {"nearest_neighbor/duplicate_key.json", {"duplicate_key.json", "line 81, column 9", "duplicate key \"rhip\"", "first at line 80"}},
  {"nearest_neighbor/huge_number.json", {"huge_number.json", "options.num_nodes", "4294967298", "out of range"}},
  {"nearest_neighbor/empty.json", {"empty.json: malformed JSON", "line 1, column 1", "unexpected end of input"}},
  {"nearest_neighbor/binary_garbage.json", {"binary_garbage.json", "line 1, column 1", "invalid literal; last read"}},
  {"nearest_neighbor/deeply_nested.json", {"deeply_nested.json", "line 4, column 266", "deeper than 256"}},

  // Wang 2009 controller JSON (load_wang2009_controller, stocky humanoid)
  {"wang2009/truncated.json", {"truncated.json", "malformed JSON", "line 96, column 13", "missing closing quote", "'\"s1.kd.sta'"}},
  {"wang2009/wrong_type_string.json", {"wrong_type_string.json", "parameters.c_trans", "\"0.01\""}},
  {"wang2009/wrong_type_array.json", {"wrong_type_array.json", "'parameters'", "got array"}},
  {"wang2009/nan.json", {"nan.json", "parameters.cd_coronal", "\"NaN\""}},
  {"wang2009/inf.json", {"inf.json", "line 9, column 17", "1e999", "too large"}},
  {"wang2009/missing_parameter.json", {"missing_parameter.json", "parameters.cd_sagittal", "missing"}},
  {"wang2009/unknown_parameter.json", {"unknown_parameter.json", "parameters.c_transs", "unknown parameter 'c_transs'"}},
  {"wang2009/duplicate_key.json", {"duplicate_key.json", "line 7, column 3", "duplicate key \"c_trans\"", "first at line 6"}},
  {"wang2009/huge_number.json", {"huge_number.json", "line 5, column 16", "1000000000000000", "400 characters", "too large"}},
  {"wang2009/empty.json", {"empty.json: malformed JSON", "line 1, column 1", "unexpected end of input"}},
  {"wang2009/binary_garbage.json", {"binary_garbage.json", "line 1, column 1", "invalid literal; last read"}},
  {"wang2009/deeply_nested.json", {"deeply_nested.json", "line 3, column 265", "deeper than 256"}},

  // Wang 2012 reflex controller JSON (load_wang2012_controller)
  {"wang2012/truncated.json", {"truncated.json", "malformed JSON", "line 70, column 8", "missing closing quote", "'\"p_GL'"}},
  {"wang2012/wrong_type_string.json", {"wrong_type_string.json", "parameters.G_SOL", "\"1.2\"", "string"}},
  {"wang2012/wrong_type_array.json", {"wrong_type_array.json", "'parameters'", "got array"}},
  {"wang2012/nan.json", {"nan.json", "parameters.G_VAS", "\"NaN\""}},
  {"wang2012/inf.json", {"inf.json", "line 11, column 12", "1e999", "too large"}},
  {"wang2012/missing_parameter.json", {"missing_parameter.json", "parameters.G_TA", "missing"}},
  {"wang2012/missing_target_speed.json", {"missing_target_speed.json", "'target_speed'", "missing"}},
  {"wang2012/unknown_parameter.json", {"unknown_parameter.json", "parameters.G_SOLL", "unknown parameter 'G_SOLL'"}},
  {"wang2012/duplicate_key.json", {"duplicate_key.json", "line 16, column 3", "duplicate key \"G_SOL\"", "first at line 15"}},
  {"wang2012/huge_number.json", {"huge_number.json", "line 5, column 16", "1000000000000000", "400 characters", "too large"}},
  {"wang2012/empty.json", {"empty.json: malformed JSON", "line 1, column 1", "unexpected end of input"}},
  {"wang2012/binary_garbage.json", {"binary_garbage.json", "line 1, column 1", "invalid literal; last read"}},
  {"wang2012/deeply_nested.json", {"deeply_nested.json", "line 3, column 265", "deeper than 256"}},

  // trajectory CSV (load_trajectory_csv)
  {"trajectory_csv/truncated.csv", {"truncated.csv", "line 12", "no end-of-line", "truncated"}},
  {"trajectory_csv/wrong_type.csv", {"wrong_type.csv", "line 12, column 5", "'abc'", "q:knee [rad]"}},
  {"trajectory_csv/nan.csv", {"nan.csv", "line 12, column 1", "'nan'", "time"}},
  {"trajectory_csv/inf.csv", {"inf.csv", "line 12, column 1", "'inf'", "time"}},
  {"trajectory_csv/out_of_range_flag.csv", {"out_of_range_flag.csv", "line 12, column 37", "'2'", "0 or 1"}},
  {"trajectory_csv/wrong_dof_count.csv", {"wrong_dof_count.csv", "line 10", "tau has 3, v has 4"}},
  {"trajectory_csv/unknown_body.csv", {"unknown_body.csv", "line 10, column 23", "body:thigh:z [m]", "'thigh'"}},
  {"trajectory_csv/duplicate_column.csv", {"duplicate_column.csv", "line 10, column 29", "'com:x [m]' repeats column 28"}},
  {"trajectory_csv/huge_number.csv", {"huge_number.csv", "line 12, column 42", "'99999999999'", "out of range"}},
  {"trajectory_csv/empty.csv", {"empty.csv'", "empty file"}},
  {"trajectory_csv/binary_garbage.csv", {"binary_garbage.csv", "line 1", "not a gaitsynth trajectory CSV", "got '"}},

  // optimizer checkpoints (load_checkpoint into sds over x0, x1)
  {"checkpoint/truncated.ckpt", {"truncated.ckpt", "line 20 (the end of the file), key 'best_value'", "truncated"}},
  {"checkpoint/wrong_type.ckpt", {"wrong_type.ckpt", "line 9, key 'iteration'", "'three'"}},
  {"checkpoint/nan.ckpt", {"nan.ckpt", "line 18, key 'theta'", "component 1 is nan"}},
  {"checkpoint/inf.ckpt", {"inf.ckpt", "line 20, key 'alpha'", "alpha is inf"}},
  {"checkpoint/wrong_vector_size.ckpt", {"wrong_vector_size.ckpt", "line 18, key 'theta'", "size 3, expected 2"}},
  {"checkpoint/unknown_parameter.ckpt", {"unknown_parameter.ckpt", "line 6, key 'parameter'", "'rhip'", "'x1'"}},
  {"checkpoint/duplicate_key.ckpt", {"duplicate_key.ckpt", "line 10, key 'evaluations'", "found 'iteration'"}},
  {"checkpoint/huge_number.ckpt", {"huge_number.ckpt", "line 23, key 'batch_values'", "number 3 of 99999999999", "'points'"}},
  {"checkpoint/empty.ckpt", {"empty.ckpt", "line 1 (the end of the file), key 'magic'", "found the end of the file"}},
  {"checkpoint/binary_garbage.ckpt", {"binary_garbage.ckpt", "line 1, key 'magic'", "expected key 'magic', found '"}},

  // normative gait CSV (load_normative_gait)
  {"normative_gait/truncated.csv", {"truncated.csv:7:", "3 fields, the header has 6"}},
  {"normative_gait/wrong_type.csv", {"wrong_type.csv:6:", "mean 'abc'"}},
  {"normative_gait/nan.csv", {"nan.csv:6:", "mean 'nan'"}},
  {"normative_gait/inf.csv", {"inf.csv:4:", "sd 'inf'"}},
  {"normative_gait/out_of_range_percent.csv", {"out_of_range_percent.csv:7:", "percent_gait_cycle 150.0000", "[0, 100]"}},
  {"normative_gait/wrong_field_count.csv", {"wrong_field_count.csv:3:", "5 fields, the header has 6"}},
  {"normative_gait/unknown_column.csv", {"unknown_column.csv:1:", "no column 'mean'", "men"}},
  {"normative_gait/duplicate_column.csv", {"duplicate_column.csv:1:", "'mean' appears twice", "columns 4 and 7"}},
  {"normative_gait/huge_number.csv", {"huge_number.csv:5:", "mean '1000000000000000", "...' is not a finite number"}},
  {"normative_gait/empty.csv", {"empty.csv:1:", "empty: expected a header line"}},
  {"normative_gait/binary_garbage.csv", {"binary_garbage.csv:1:", "no column 'speed_mps'", "(header: '"}},
};
// clang-format on

/// The optimizer the checkpoints were written by (sds over two unbounded parameters x0, x1).
sds checkpoint_optimizer() {
  return sds(parameter_space::unbounded(Eigen::Vector2d(0.5, -0.25)), sds_options{});
}

/// The complete state of an optimizer as its checkpoint text: equal strings, equal state bit for
/// bit (doubles as hexadecimal floats).
template <class O>
std::string state_of(const O& opt) {
  std::ostringstream os;
  checkpoint_writer w(os);
  opt.save(w);
  return os.str();
}

/// Loads `file` with the loader of its folder (which it names first).
void load(const std::string& file) {
  static const planar_model human7 = sharon2005_human7();
  static const auto stocky = wang2009_humanoid(wang2009_shape::stocky);
  static const wang2009_controller stocky_controller(stocky);
  const fs::path path = corpus / file;
  const std::string loader = file.substr(0, file.find('/'));
  if (loader == "keyframes") {
    (void)load_keyframes(human7, path);
  } else if (loader == "nearest_neighbor") {
    (void)load_nearest_neighbor(human7, path);
  } else if (loader == "wang2009") {
    (void)load_wang2009_controller(path.string(), stocky_controller);
  } else if (loader == "wang2012") {
    (void)load_wang2012_controller(path.string());
  } else if (loader == "trajectory_csv") {
    (void)load_trajectory_csv(path.string());
  } else if (loader == "checkpoint") {
    sds opt = checkpoint_optimizer();
    load_checkpoint(opt, path);
  } else if (loader == "normative_gait") {
    (void)load_normative_gait(path.string());
  } else {
    FAIL("no loader for " << file);
  }
}

}  // namespace

TEST_CASE("bad inputs: the table lists every file of the corpus", "[io][bad_inputs]") {
  std::set<std::string> listed = {"README.md", "make_binary.py"};
  for (const bad_file& b : table) CHECK(listed.insert(b.path).second);  // no file twice
  std::set<std::string> loaders;
  for (const bad_file& b : table) loaders.insert(b.path.substr(0, b.path.find('/')));
  for (const std::string& l : loaders)
    for (const auto& e : fs::directory_iterator(corpus / l))
      if (e.path().stem() == "valid") listed.insert(l + "/" + e.path().filename().string());
  std::set<std::string> present;
  for (const auto& e : fs::recursive_directory_iterator(corpus))
    if (e.is_regular_file()) present.insert(fs::relative(e.path(), corpus).generic_string());
  CHECK(present == listed);
  CHECK(loaders.size() == 7);
}

TEST_CASE("bad inputs: the valid file each defect was made from loads", "[io][bad_inputs]") {
  for (const char* file : {"keyframes/valid.json", "nearest_neighbor/valid.json",
                           "wang2009/valid.json", "wang2012/valid.json", "trajectory_csv/valid.csv",
                           "checkpoint/valid.ckpt", "normative_gait/valid.csv"}) {
    INFO(file);
    CHECK_NOTHROW(load(file));
  }
}

TEST_CASE("bad inputs: every file is refused naming the file, the place and the value",
          "[io][bad_inputs]") {
  for (const bad_file& b : table) {
    INFO(b.path);
    std::string what;
    try {
      load(b.path);
    } catch (const std::exception& e) {
      what = e.what();
    }
    INFO("what(): " << what);
    REQUIRE_FALSE(what.empty());  // no exception (or one with an empty message)
    for (const std::string& s : b.expected) CHECK_THAT(what, Catch::Contains(s));
  }
}

TEST_CASE("bad inputs: a failed load_checkpoint leaves the optimizer as it was",
          "[io][bad_inputs][optimizers]") {
  const auto sphere = [](const Eigen::VectorXd& x) { return x.squaredNorm(); };
  SECTION("sds, every checkpoint of the corpus") {
    sds opt = checkpoint_optimizer();
    minimize(opt, sphere, run_options{}, [](const optimizer_status& s) { return s.iteration < 5; });
    const std::string before = state_of(opt);
    const Eigen::VectorXd theta = opt.theta();
    const double step = opt.step();
    const auto iteration = opt.status().iteration;
    for (const bad_file& b : table) {
      if (b.path.rfind("checkpoint/", 0) != 0) continue;
      INFO(b.path);
      CHECK_THROWS_AS(load_checkpoint(opt, corpus / b.path), checkpoint_error);
      CHECK(state_of(opt) == before);
      CHECK((opt.theta().array() == theta.array()).all());
      CHECK(opt.step() == step);
      CHECK(opt.status().iteration == iteration);
    }
    // And the valid one does load (the state changes).
    load_checkpoint(opt, corpus / "checkpoint/valid.ckpt");
    CHECK(state_of(opt) != before);
  }
  SECTION("cmaes and cmaes_restarts, refused late in the file") {
    const fs::path dir = fs::path(GAITSYNTH_BINARY_DIR) / "test_scratch" / "io" / "bad_inputs";
    fs::create_directories(dir);
    cmaes_options o;
    o.sigma0 = 0.3;
    o.seed = 3;
    const auto space = parameter_space::unbounded(Eigen::Vector3d(0.5, -0.25, 1.0));
    const auto until = [](int n) {
      return [n](const optimizer_status& s) { return s.iteration < n; };
    };
    // A checkpoint after 6 iterations, then copies with one defect each.
    cmaes a(space, o);
    minimize(a, sphere, run_options{}, until(6));
    save_checkpoint(a, dir / "cmaes.ckpt");
    std::string text;
    {
      std::ifstream in(dir / "cmaes.ckpt");
      text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const auto sigma_at = text.find("\nsigma ") + 7;
    const auto sigma_end = text.find('\n', sigma_at);
    std::ofstream(dir / "nan_sigma.ckpt")
        << text.substr(0, sigma_at) << "nan" << text.substr(sigma_end);
    std::ofstream(dir / "cut.ckpt") << text.substr(0, text.rfind("candidates"));
    // The optimizer to load into: 2 iterations of its own.
    cmaes b(space, o);
    minimize(b, sphere, run_options{}, until(2));
    const std::string before = state_of(b);
    const Eigen::VectorXd mean = b.mean();
    const double sigma = b.sigma();
    const auto iteration = b.iteration();
    CHECK_THROWS_WITH(load_checkpoint(b, dir / "nan_sigma.ckpt"),
                      Catch::Contains("nan_sigma.ckpt") && Catch::Contains("key 'sigma'") &&
                          Catch::Contains("nan"));
    CHECK_THROWS_WITH(load_checkpoint(b, dir / "cut.ckpt"),
                      Catch::Contains("cut.ckpt") && Catch::Contains("key 'candidates'") &&
                          Catch::Contains("end of the file"));
    CHECK(state_of(b) == before);
    CHECK((b.mean().array() == mean.array()).all());
    CHECK(b.sigma() == sigma);
    CHECK(b.iteration() == iteration);
    load_checkpoint(b, dir / "cmaes.ckpt");
    CHECK(state_of(b) == state_of(a));

    // cmaes_restarts is not copyable: its current run is rebuilt while loading, then put back.
    cmaes_restarts r(space, o, restart_options{.strategy = restart_strategy::ipop});
    minimize(r, sphere, run_options{}, until(4));
    save_checkpoint(r, dir / "restarts.ckpt");
    {
      std::ifstream in(dir / "restarts.ckpt");
      text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::ofstream(dir / "restarts_cut.ckpt") << text.substr(0, text.rfind("candidates"));
    cmaes_restarts r2(space, o, restart_options{.strategy = restart_strategy::ipop});
    minimize(r2, sphere, run_options{}, until(1));
    const std::string before_r = state_of(r2);
    CHECK_THROWS_WITH(load_checkpoint(r2, dir / "restarts_cut.ckpt"),
                      Catch::Contains("restarts_cut.ckpt") && Catch::Contains("'candidates'"));
    CHECK(state_of(r2) == before_r);
    // A corrupt count of finished runs fails as a short file, at the first run record missing,
    // before anything is allocated for it (tests/fuzz/checkpoint.fuzz.cpp found 6296478855 run
    // records allocated first: std::bad_alloc, or AddressSanitizer's out-of-memory abort).
    const auto runs_at = text.find("\nfinished_runs ") + 15;
    std::ofstream(dir / "restarts_runs.ckpt")
        << text.substr(0, runs_at) << "6296478855" << text.substr(text.find('\n', runs_at));
    CHECK_THROWS_WITH(load_checkpoint(r2, dir / "restarts_runs.ckpt"),
                      Catch::Contains("restarts_runs.ckpt") &&
                          Catch::Contains("'finished_run_lambda'") &&
                          !Catch::Contains("bad_alloc"));
    CHECK(state_of(r2) == before_r);
    load_checkpoint(r2, dir / "restarts.ckpt");
    CHECK(state_of(r2) == state_of(r));
  }
}
