// Trajectory CSV (io/trajectory_csv.hpp): the bytes of a small file pinned, the header equal to
// the schema's layout of trajectory_channels, every channel's values read back exactly, header
// units, and clear errors (file, line, column, header cell) for malformed and truncated files.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "gaitsynth/io/trajectory_csv.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

namespace {

void require_equal(const trajectory& a, const trajectory& b, double tol) {
  REQUIRE(a.model_name == b.model_name);
  REQUIRE(a.planar == b.planar);
  REQUIRE(a.q_names == b.q_names);
  REQUIRE(a.v_names == b.v_names);
  REQUIRE(a.body_names == b.body_names);
  REQUIRE(a.body_parents == b.body_parents);
  REQUIRE(a.contact_names == b.contact_names);
  REQUIRE(a.contact_bodies == b.contact_bodies);
  REQUIRE(a.objective_term_names == b.objective_term_names);
  REQUIRE(a.terrain.nx == b.terrain.nx);
  REQUIRE(a.terrain.ny == b.terrain.ny);
  REQUIRE(a.terrain.x0 == b.terrain.x0);
  REQUIRE(a.terrain.height == b.terrain.height);
  REQUIRE(a.frames.size() == b.frames.size());
  auto close = [tol](double x, double y) {
    return x == y || std::abs(x - y) <= tol * (1 + std::abs(x));
  };
  for (std::size_t f = 0; f < a.frames.size(); ++f) {
    const auto &x = a.frames[f], &y = b.frames[f];
    INFO("frame " << f);
    REQUIRE(close(x.t, y.t));
    REQUIRE(x.q.size() == y.q.size());
    for (Eigen::Index i = 0; i < x.q.size(); ++i) REQUIRE(close(x.q[i], y.q[i]));
    REQUIRE(x.v.size() == y.v.size());
    for (Eigen::Index i = 0; i < x.v.size(); ++i) REQUIRE(close(x.v[i], y.v[i]));
    REQUIRE(x.tau.size() == y.tau.size());
    for (Eigen::Index i = 0; i < x.tau.size(); ++i) REQUIRE(close(x.tau[i], y.tau[i]));
    REQUIRE(x.body_position.size() == y.body_position.size());
    for (std::size_t b = 0; b < x.body_position.size(); ++b) {
      for (int k = 0; k < 3; ++k) REQUIRE(close(x.body_position[b][k], y.body_position[b][k]));
      REQUIRE(close(x.body_orientation[b].w(), y.body_orientation[b].w()));
      for (int k = 0; k < 3; ++k)
        REQUIRE(close(x.body_orientation[b].vec()[k], y.body_orientation[b].vec()[k]));
    }
    for (int k = 0; k < 3; ++k) REQUIRE(close(x.com[k], y.com[k]));
    REQUIRE(x.contact_active == y.contact_active);
    for (std::size_t c = 0; c < x.contact_position.size(); ++c)
      for (int k = 0; k < 3; ++k) {
        REQUIRE(close(x.contact_position[c][k], y.contact_position[c][k]));
        REQUIRE(close(x.contact_force[c][k], y.contact_force[c][k]));
      }
    REQUIRE(x.pushes.size() == y.pushes.size());
    for (std::size_t p = 0; p < x.pushes.size(); ++p) {
      REQUIRE(x.pushes[p].first == y.pushes[p].first);
      for (int k = 0; k < 3; ++k) REQUIRE(close(x.pushes[p].second[k], y.pushes[p].second[k]));
    }
    REQUIRE(x.objective_terms.size() == y.objective_terms.size());
    for (std::size_t o = 0; o < x.objective_terms.size(); ++o)
      REQUIRE(close(x.objective_terms[o], y.objective_terms[o]));
    REQUIRE(x.controller_state == y.controller_state);
  }
}

trajectory sample_trajectory() {
  const auto m = viz_test::make_biped<floating_root>();
  auto traj = viz_test::make_walk(m, 1.2, 0.01);
  traj.terrain.nx = 3;
  traj.terrain.ny = 2;
  traj.terrain.x0 = -1.5;
  traj.terrain.height = {0, 0.01, 0.02, 1.0 / 3.0, -0.5, 1e-17};
  traj.frames[7].pushes.emplace_back(m.body_index("torso"), Eigen::Vector3d(1.0 / 7, -2, 3));
  traj.frames[3].objective_terms[1] = std::numeric_limits<double>::infinity();
  return traj;
}

std::string to_csv(const trajectory& t, trajectory_csv_options o = {}) {
  std::ostringstream s;
  write_trajectory_csv(t, s, o);
  return s.str();
}

trajectory from_csv(const std::string& text) {
  std::istringstream s(text);
  return read_trajectory_csv(s, "test.csv");
}

/// The line of text that holds the header (the first one not starting with '#').
std::string header_of(const std::string& text) {
  std::istringstream is(text);
  std::string line;
  while (std::getline(is, line))
    if (line.empty() || line[0] != '#') break;
  return line;
}

/// The error read_trajectory_csv throws for text (fails the test when it throws none).
trajectory_csv_error read_error(const std::string& text) {
  try {
    from_csv(text);
  } catch (const trajectory_csv_error& e) {
    return e;
  }
  FAIL("no trajectory_csv_error");
  return trajectory_csv_error("", 0, 0);
}

/// text with the first occurrence of `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  REQUIRE(p != std::string::npos);
  return text.replace(p, from.size(), to);
}

/// A planar two-body trajectory recording every channel, small enough to pin byte for byte.
trajectory tiny_trajectory() {
  trajectory t;
  t.model_name = "tiny";
  t.planar = true;
  t.q_names = {"root_x", "root_z", "root_pitch", "knee"};
  t.v_names = t.q_names;
  t.body_names = {"pelvis", "shin"};
  t.body_parents = {-1, 0};
  t.contact_names = {"toe"};
  t.contact_bodies = {1};
  t.objective_term_names = {"distance"};
  t.terrain = {.x0 = -1, .y0 = -0.5, .dx = 0.25, .dy = 1, .nx = 2, .ny = 1, .height = {0, 0.5}};
  for (int k = 0; k < 2; ++k) {
    trajectory_frame f;
    f.t = 0.01 * k;
    f.q = Eigen::Vector4d(0.1 * k, 0.9, -0.05, 0.25 + k);
    f.v = Eigen::Vector4d(1.5, -0.125, 0.5, 2);
    f.tau = Eigen::Vector4d(0, 0, 0, -30.5 * (k + 1));
    f.body_position = {Eigen::Vector3d(0.1 * k, 0, 0.9), Eigen::Vector3d(0.1, 0, 0.45)};
    f.body_orientation = {Eigen::Quaterniond(1, 0, 0, 0), Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5)};
    f.com = Eigen::Vector3d(0.05, 0, 0.8);
    f.contact_position = {Eigen::Vector3d(0.2, 0, 1.0 / 3.0)};
    f.contact_force = {Eigen::Vector3d(-1, 0, 300 * k)};
    f.contact_active = {static_cast<unsigned char>(k)};
    if (k == 1) f.pushes = {{1, Eigen::Vector3d(20, 0, 0)}, {1, Eigen::Vector3d(5, 0, -1)}};
    f.objective_terms = {0.125 * k};
    f.controller_state = 3 * k - 1;
    t.frames.push_back(f);
  }
  return t;
}

}  // namespace

TEST_CASE("trajectory CSV: write then read gives the same trajectory", "[io][csv]") {
  const trajectory traj = sample_trajectory();
  const std::string text = to_csv(traj);
  SECTION("shortest exact digits") {
    require_equal(traj, from_csv(text), 0.0);
  }
  SECTION("6 significant digits: equal to printed precision") {
    require_equal(traj, from_csv(to_csv(traj, {.precision = 6})), 5e-6);
  }
  SECTION("a planar trajectory without body poses, v or contacts") {
    const auto m = viz_test::make_biped<planar_root>();
    trajectory t;
    t.q_names = q_coordinate_names(m);
    for (int k = 0; k < 3; ++k) {
      trajectory_frame f;
      f.t = 0.5 * k;
      f.q = Eigen::VectorXd::LinSpaced(m.nq(), 0, k);
      t.frames.push_back(f);
    }
    t.planar = true;
    require_equal(t, from_csv(to_csv(t)), 0.0);
  }
  SECTION("file round trip") {
    const std::string path = std::string(GAITSYNTH_BINARY_DIR) + "/viz_roundtrip.csv";
    save_trajectory_csv(traj, path);
    require_equal(traj, load_trajectory_csv(path), 0.0);
    CHECK_THROWS_WITH(load_trajectory_csv(path + ".missing"), Catch::Contains("cannot open"));
  }
}

TEST_CASE("trajectory CSV: the header names every column with its unit", "[io][csv]") {
  const trajectory traj = sample_trajectory();
  const std::string text = to_csv(traj);
  std::istringstream is(text);
  std::string line, header;
  while (std::getline(is, line))
    if (line[0] != '#') {
      header = line;
      break;
    }
  for (const char* col :
       {"t [s]", "q:root_x [m]", "q:root_qw [1]", "q:lknee [rad]", "v:root_x [m/s]",
        "v:root_wx [rad/s]", "v:lknee [rad/s]", "tau:root_z [N]", "tau:lhip_x [N m]",
        "body:lfoot:qz [1]", "body:pelvis:x [m]", "com:z [m]", "contact:lheel:fz [N]",
        "contact:rtoe:active [1]", "push:pelvis:fy [N]", "push:torso:fx [N]", "obj:effort [-]",
        "controller_state [1]"})
    CHECK(header.find(col) != std::string::npos);
  // Every column has a unit: count cells and bracketed units.
  std::size_t cells = 1, units = 0;
  for (std::size_t i = 0; i < header.size(); ++i) {
    cells += header[i] == ',';
    units += header[i] == '[';
  }
  CHECK(cells == units);
  CHECK(text.find("# frames: 121\n") != std::string::npos);
}

TEST_CASE("trajectory CSV: malformed and truncated files throw naming line and column",
          "[io][csv]") {
  const trajectory traj = sample_trajectory();
  const std::string text = to_csv(traj);
  // Line numbers of the header and the first data row.
  int header_line = 0;
  {
    std::istringstream is(text);
    std::string l;
    while (std::getline(is, l)) {
      ++header_line;
      if (l[0] != '#') break;
    }
  }
  const int first_row = header_line + 1;
  auto nth_line_start = [&](int n) {
    std::size_t p = 0;
    for (int k = 1; k < n; ++k) p = text.find('\n', p) + 1;
    return p;
  };
  SECTION("a value that is not a number") {
    std::string bad = text;
    const std::size_t row = nth_line_start(first_row + 2);
    const std::size_t c2 = bad.find(',', bad.find(',', row) + 1);  // after the 2nd field
    bad.insert(c2, "abc");
    try {
      from_csv(bad);
      FAIL("no exception");
    } catch (const trajectory_csv_error& e) {
      CHECK(e.line() == first_row + 2);
      CHECK(e.column() == 2);
      CHECK_THAT(e.what(), Catch::Contains("test.csv") &&
                               Catch::Contains("line " + std::to_string(first_row + 2)) &&
                               Catch::Contains("column 2") && Catch::Contains("q:root_x [m]") &&
                               Catch::Contains("abc"));
    }
  }
  SECTION("truncated in the middle of a line") {
    const std::string cut = text.substr(0, nth_line_start(first_row + 10) + 40);
    CHECK_THROWS_WITH(from_csv(cut), Catch::Contains("line " + std::to_string(first_row + 10)) &&
                                         Catch::Contains("truncated"));
  }
  SECTION("truncated at a line boundary") {
    const std::string cut = text.substr(0, nth_line_start(first_row + 10));
    CHECK_THROWS_WITH(from_csv(cut), Catch::Contains("declares 121 frames, found 10"));
  }
  SECTION("last value cut without its end of line") {
    const std::string cut = text.substr(0, text.size() - 2);
    CHECK_THROWS_WITH(from_csv(cut), Catch::Contains("no end-of-line"));
  }
  SECTION("cut inside the metadata or before the header") {
    CHECK_THROWS_WITH(from_csv(text.substr(0, nth_line_start(header_line))),
                      Catch::Contains("missing header"));
    CHECK_THROWS_WITH(from_csv(""), Catch::Contains("empty file"));
  }
  SECTION("a row with an extra field") {
    std::string bad = text;
    bad.insert(nth_line_start(first_row + 1) + 3, ",");
    CHECK_THROWS_WITH(from_csv(bad), Catch::Contains("line " + std::to_string(first_row + 1)) &&
                                         Catch::Contains("fields"));
  }
  SECTION("not a gaitsynth trajectory") {
    CHECK_THROWS_WITH(
        from_csv("t [s],x [m]\n0,1\n"),
        Catch::Contains("line 1") && Catch::Contains("not a gaitsynth trajectory CSV"));
  }
  SECTION("a header cell without unit or of unknown kind") {
    std::string bad = text;
    const std::size_t h = nth_line_start(header_line);
    bad.replace(h, 5, "t");  // "t [s]" -> "t"
    CHECK_THROWS_WITH(from_csv(bad), Catch::Contains("column 1") && Catch::Contains("no unit"));
    bad = text;
    const std::size_t c = bad.find("com:x [m]");
    bad.replace(c, 9, "zzz:x [m]");
    CHECK_THROWS_WITH(from_csv(bad), Catch::Contains("unknown column 'zzz:x [m]'"));
  }
  SECTION("an active flag that is not 0 or 1") {
    std::string bad = text;
    const std::size_t row = nth_line_start(first_row);
    // The active column of lheel: find its index in the header and replace that field.
    std::istringstream is(text.substr(nth_line_start(header_line)));
    std::string header;
    std::getline(is, header);
    int col = 0;
    for (std::size_t i = 0; i < header.find("contact:lheel:active"); ++i) col += header[i] == ',';
    std::size_t p = row;
    for (int k = 0; k < col; ++k) p = bad.find(',', p) + 1;
    bad.replace(p, 1, "2");
    CHECK_THROWS_WITH(from_csv(bad), Catch::Contains("must be 0 or 1") &&
                                         Catch::Contains("column " + std::to_string(col + 1)));
  }
}

TEST_CASE("trajectory CSV: inconsistent trajectories are rejected when writing", "[io][csv]") {
  trajectory traj = sample_trajectory();
  traj.frames[5].q.resize(3);
  CHECK_THROWS_WITH(to_csv(traj), Catch::Contains("frame 5") && Catch::Contains("q"));
  traj = sample_trajectory();
  traj.body_names[1] = "a,b";
  CHECK_THROWS_WITH(to_csv(traj), Catch::Contains("'a,b'"));
  traj = sample_trajectory();
  traj.frames[2].objective_terms.pop_back();
  CHECK_THROWS_WITH(to_csv(traj), Catch::Contains("frame 2") && Catch::Contains("objective"));
}

TEST_CASE("trajectory CSV: a small trajectory is written byte for byte as documented",
          "[io][csv]") {
  // Pinned from the writer before the schema split: existing files stay readable and identical.
  const std::string expected =
      "# gaitsynth trajectory csv 1\n"
      "# model: tiny\n"
      "# planar: 1\n"
      "# frames: 2\n"
      "# body: 0 -1 pelvis\n"
      "# body: 1 0 shin\n"
      "# contact: 0 1 toe\n"
      "# terrain: -1 -0.5 0.25 1 2 1\n"
      "# terrain_heights: 0 0.5\n"
      "t [s],q:root_x [m],q:root_z [m],q:root_pitch [rad],q:knee [rad],v:root_x [m/s],"
      "v:root_z [m/s],v:root_pitch [rad/s],v:knee [rad/s],tau:root_x [N],tau:root_z [N],"
      "tau:root_pitch [N m],tau:knee [N m],body:pelvis:x [m],body:pelvis:y [m],body:pelvis:z [m],"
      "body:pelvis:qw [1],body:pelvis:qx [1],body:pelvis:qy [1],body:pelvis:qz [1],"
      "body:shin:x [m],body:shin:y [m],body:shin:z [m],body:shin:qw [1],body:shin:qx [1],"
      "body:shin:qy [1],body:shin:qz [1],com:x [m],com:y [m],com:z [m],contact:toe:x [m],"
      "contact:toe:y [m],contact:toe:z [m],contact:toe:fx [N],contact:toe:fy [N],"
      "contact:toe:fz [N],contact:toe:active [1],push:shin:fx [N],push:shin:fy [N],"
      "push:shin:fz [N],obj:distance [-],controller_state [1]\n"
      "0,0,0.9,-0.05,0.25,1.5,-0.125,0.5,2,0,0,0,-30.5,0,0,0.9,1,0,0,0,0.1,0,0.45,0.5,0.5,0.5,0.5,"
      "0.05,0,0.8,0.2,0,0.3333333333333333,-1,0,0,0,0,0,0,0,-1\n"
      "0.01,0.1,0.9,-0.05,1.25,1.5,-0.125,0.5,2,0,0,0,-61,0.1,0,0.9,1,0,0,0,0.1,0,0.45,0.5,0.5,0.5,"
      "0.5,0.05,0,0.8,0.2,0,0.3333333333333333,-1,0,300,1,25,0,-1,0.125,2\n";
  const trajectory t = tiny_trajectory();
  CHECK(to_csv(t) == expected);
  // Read back and written again: the same bytes (the two pushes on the shin become their sum).
  const trajectory back = from_csv(expected);
  CHECK(to_csv(back) == expected);
  REQUIRE(back.frames[1].pushes.size() == 1);
  CHECK(back.frames[1].pushes[0].first == 1);
  CHECK(back.frames[1].pushes[0].second == Eigen::Vector3d(25, 0, -1));
  CHECK(back.frames[0].pushes.empty());
}

TEST_CASE("trajectory CSV: the header is the schema's layout of trajectory_channels", "[io][csv]") {
  namespace tc = detail::trajectory_csv;
  for (const trajectory& t : {sample_trajectory(), tiny_trajectory()}) {
    const std::vector<bool> present = tc::recorded_channels(t);
    const std::vector<tc::column> cols = tc::layout(t, present, tc::pushed_bodies(t));
    std::string joined;
    for (std::size_t i = 0; i < cols.size(); ++i) joined += (i ? "," : "") + cols[i].cell;
    CHECK(header_of(to_csv(t)) == joined);
    // Both fixtures record every channel, so each one has columns (a new channel needs data here).
    for (std::size_t c = 0; c < tc::channel_count; ++c) {
      INFO("channel " << trajectory_channels[c].member);
      CHECK(present[c]);
      CHECK(std::count_if(cols.begin(), cols.end(),
                          [c](const tc::column& col) { return col.channel == c; }) > 0);
    }
  }
  // A channel a trajectory leaves empty has no columns; the names of v survive without frames.
  trajectory t = tiny_trajectory();
  for (auto& f : t.frames) {
    f.tau.resize(0);
    f.contact_force.clear();
  }
  const std::string h = header_of(to_csv(t));
  CHECK(h.find("tau:") == std::string::npos);
  CHECK(h.find(":fz [N],contact") == std::string::npos);
  CHECK(h.find("contact:toe:z [m],contact:toe:active [1]") != std::string::npos);
  t.frames.clear();
  CHECK(from_csv(to_csv(t)).v_names == t.v_names);
}

TEST_CASE("trajectory CSV: every channel can be written and read", "[io][csv]") {
  for (const trajectory_channel& ch : trajectory_channels) {
    INFO(ch.member);
    CHECK(ch.get != nullptr);
    CHECK(ch.set != nullptr);
    if (ch.when != trajectory_channel::presence::always) {
      CHECK(ch.size != nullptr);  // to decide whether frames record it
      CHECK(ch.resize != nullptr);
    }
  }
}

TEST_CASE("trajectory CSV: every channel reads back exactly, value by value", "[io][csv]") {
  namespace tc = detail::trajectory_csv;
  // Give every column of every frame its own value through the channel list, so that a channel
  // whose get() and set() disagree, or two columns read into one member, show up.
  trajectory t = sample_trajectory();
  for (auto& f : t.frames) f.pushes = {{0, Eigen::Vector3d(1, 2, 3)}, {3, Eigen::Vector3d::Zero()}};
  const std::vector<tc::column> cols =
      tc::layout(t, tc::recorded_channels(t), tc::pushed_bodies(t));
  int n = 0;
  for (auto& f : t.frames) {
    for (const tc::column& c : cols) {
      const trajectory_channel& ch = trajectory_channels[c.channel];
      ++n;
      const double x = ch.type == trajectory_channel::value::flag      ? n % 2
                       : ch.type == trajectory_channel::value::integer ? n - 5000
                                                                       : 1.0 / (n + 7) - 0.01;
      ch.set(f, c.item, c.component, x);
    }
    for (const auto& ch : trajectory_channels)
      if (ch.finish != nullptr) ch.finish(f);
  }
  const trajectory back = from_csv(to_csv(t));
  REQUIRE(back.frames.size() == t.frames.size());
  for (std::size_t f = 0; f < t.frames.size(); ++f)
    for (const tc::column& c : cols) {
      const trajectory_channel& ch = trajectory_channels[c.channel];
      const double a = ch.get(t.frames[f], c.item, c.component);
      const double b = ch.get(back.frames[f], c.item, c.component);
      INFO("frame " << f << ", " << c.cell);
      CHECK(std::memcmp(&a, &b, sizeof a) == 0);
    }
  require_equal(t, back, 0.0);
}

TEST_CASE("trajectory CSV: bad header cells and rows name the line, column and header cell",
          "[io][csv][bad_input]") {
  const std::string text = to_csv(tiny_trajectory());
  const int header_line = 10, first_row = 11;
  SECTION("a missing header column is named by its header text") {
    for (const char* cell : {"com:y [m],", "body:shin:qz [1],", "contact:toe:fx [N],",
                             "push:shin:fy [N],", ",controller_state [1]"}) {
      std::string name = cell;
      name.erase(std::remove(name.begin(), name.end(), ','), name.end());
      const trajectory_csv_error e = read_error(replaced(text, cell, ""));
      CHECK(e.line() == header_line);
      CHECK_THAT(e.what(), Catch::Contains("test.csv") &&
                               Catch::Contains("line " + std::to_string(header_line)) &&
                               Catch::Contains("missing column '" + name + "'"));
    }
    // Positions without orientations (or the reverse): the pose comes whole.
    std::string bad = text;
    for (const char* c : {"qw", "qx", "qy", "qz"})
      for (const char* b : {"pelvis", "shin"})
        bad = replaced(bad, std::string("body:") + b + ":" + c + " [1],", "");
    CHECK_THAT(read_error(bad).what(), Catch::Contains("missing column 'body:pelvis:qw [1]'"));
  }
  SECTION("a wrong unit, a repeated column, a misplaced time") {
    trajectory_csv_error e = read_error(replaced(text, "q:knee [rad]", "q:knee [deg]"));
    CHECK(e.line() == header_line);
    CHECK(e.column() == 5);
    CHECK_THAT(e.what(), Catch::Contains("q:knee [deg]") && Catch::Contains("[rad]"));
    e = read_error(replaced(text, "com:y [m]", "com:x [m]"));
    CHECK(e.column() == 29);
    CHECK_THAT(e.what(),
               Catch::Contains("column 29") && Catch::Contains("'com:x [m]' repeats column 28"));
    e = read_error(replaced(text, "t [s],q:root_x [m]", "q:root_x [m],t [s]"));
    CHECK(e.column() == 1);
    CHECK_THAT(e.what(), Catch::Contains("first column must be 't [s]'"));
    e = read_error(replaced(text, "tau:knee", "tau:kne"));
    CHECK_THAT(e.what(), Catch::Contains("'kne'") && Catch::Contains("'knee'"));
    e = read_error(replaced(text, "q:root_x [m]", "q [m]"));
    CHECK(e.column() == 2);
  }
  SECTION("a row with the wrong number of fields names its line") {
    const std::string row = "0,0,0.9,";
    trajectory_csv_error e = read_error(replaced(text, row, "0,0,"));
    CHECK(e.line() == first_row);
    CHECK_THAT(e.what(), Catch::Contains("line " + std::to_string(first_row)) &&
                             Catch::Contains("expected 42 fields, got 41 (truncated line?)"));
    e = read_error(replaced(text, row, "0,0,0.9,7,"));
    CHECK(e.line() == first_row);
    CHECK_THAT(e.what(), Catch::Contains("expected 42 fields, got 43"));
  }
  SECTION("a value that is not a number, not a flag or not an int names line, column and cell") {
    trajectory_csv_error e = read_error(replaced(text, "0.01,0.1,0.9", "0.01,0.1,0.9x"));
    CHECK(e.line() == first_row + 1);
    CHECK(e.column() == 3);
    CHECK_THAT(e.what(), Catch::Contains("line 12, column 3") && Catch::Contains("'0.9x'") &&
                             Catch::Contains("q:root_z [m]"));
    e = read_error(replaced(text, "0.01,0.1,0.9", "0.01,,0.9"));
    CHECK(e.column() == 2);
    CHECK_THAT(e.what(), Catch::Contains("empty value in column 'q:root_x [m]'"));
    e = read_error(replaced(text, ",0.125,2\n", ",0.125,2.5\n"));
    CHECK(e.column() == 42);
    CHECK_THAT(e.what(), Catch::Contains("as an integer") && Catch::Contains("controller_state"));
    e = read_error(replaced(text, ",0.125,2\n", ",0.125,99999999999\n"));
    CHECK_THAT(e.what(), Catch::Contains("out of range") && Catch::Contains("column 42"));
    e = read_error(replaced(text, ",300,1,", ",300,0.5,"));
    CHECK(e.column() == 37);
    CHECK_THAT(e.what(),
               Catch::Contains("must be 0 or 1") && Catch::Contains("contact:toe:active [1]"));
  }
}

TEST_CASE("trajectory CSV: body poses without orientations are rejected when writing",
          "[io][csv][bad_input]") {
  trajectory t = tiny_trajectory();
  for (auto& f : t.frames) f.body_orientation.clear();
  CHECK_THROWS_WITH(to_csv(t), Catch::Contains("frame 0") && Catch::Contains("body_orientation"));
  t = tiny_trajectory();
  for (auto& f : t.frames) f.body_position.clear();
  CHECK_THROWS_WITH(
      to_csv(t), Catch::Contains("body_orientation") && Catch::Contains("body_position has none"));
  t = tiny_trajectory();
  t.frames[1].contact_force.clear();
  CHECK_THROWS_WITH(to_csv(t), Catch::Contains("frame 1: contact_force has 0 entries"));
}
