// Trajectory CSV (io/trajectory_csv.hpp): exact round trip, header units, and clear errors for
// malformed and truncated files.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

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

}  // namespace

TEST_CASE("trajectory CSV: write then read gives the same trajectory", "[viz][csv]") {
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

TEST_CASE("trajectory CSV: the header names every column with its unit", "[viz][csv]") {
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
          "[viz][csv]") {
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

TEST_CASE("trajectory CSV: inconsistent trajectories are rejected when writing", "[viz][csv]") {
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
