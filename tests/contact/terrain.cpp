// Terrain policies: heights, normals (against finite differences of the height), clamping,
// seeded generators, vertical faces of steps, and bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/contact/terrain.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Normal from central differences of the height: (-hx, -hy, 1) normalized.
template <class T>
vec3 fd_normal(const T& t, double x, double y, double e = 1e-6) {
  const double hx = (t.height(x + e, y) - t.height(x - e, y)) / (2 * e);
  const double hy = (t.height(x, y + e) - t.height(x, y - e)) / (2 * e);
  return vec3(-hx, -hy, 1.0).normalized();
}
}  // namespace

TEST_CASE("flat_terrain: constant height, +z normal, bad height throws", "[contact][terrain]") {
  STATIC_REQUIRE(terrain<flat_terrain>);
  const flat_terrain t(0.25);
  CHECK(t.height(-3.0, 7.0) == 0.25);
  CHECK(t.normal(1.0, 2.0) == vec3::UnitZ());
  const auto c = terrain_penetration(t, vec3(4.0, -1.0, 0.2));
  CHECK(c.depth == Approx(0.05));
  CHECK(flat_terrain().height(0, 0) == 0.0);
  CHECK_THROWS_WITH(flat_terrain(kNaN), Contains("height") && Contains("nan"));
  CHECK_THROWS_AS(flat_terrain(kInf), std::invalid_argument);
}

TEST_CASE("slope_terrain: rises along its direction, normal matches finite differences",
          "[contact][terrain]") {
  const double a = 12.0 * std::numbers::pi / 180.0;  // Wang et al. 2009's steepest uphill walker
  SECTION("default direction +x") {
    const slope_terrain t(a, 0.1);
    CHECK(t.height(0.0, 5.0) == Approx(0.1));
    CHECK(t.height(2.0, -3.0) == Approx(0.1 + 2.0 * std::tan(a)));
    const vec3 n = t.normal(1.0, 0.0);
    CHECK(n.norm() == Approx(1.0));
    CHECK(n.isApprox(vec3(-std::sin(a), 0.0, std::cos(a)), 1e-14));
    CHECK(n.dot(t.uphill()) == Approx(0.0).margin(1e-15));
    CHECK(t.uphill().z() == Approx(std::sin(a)));
    // Depth along the normal is the exact distance to the plane.
    const vec3 p(1.0, 0.0, t.height(1.0, 0.0) - 0.01);
    CHECK(terrain_penetration(t, p).depth == Approx(0.01 * std::cos(a)));
    const vec3 on_plane = vec3(1.0, 0.0, t.height(1.0, 0.0)) - 0.003 * n;
    CHECK(terrain_penetration(t, on_plane).depth == Approx(0.003).epsilon(1e-12));
  }
  SECTION("any direction and origin") {
    const Eigen::Vector2d d(1.0, 2.0), o(0.5, -1.0);
    const slope_terrain t(-a, 0.3, 3.0 * d, o);
    CHECK(t.height(o.x(), o.y()) == Approx(0.3));
    const Eigen::Vector2d step = d.normalized() * 2.0;
    CHECK(t.height(o.x() + step.x(), o.y() + step.y()) == Approx(0.3 - 2.0 * std::tan(a)));
    // Perpendicular to the direction the height does not change.
    CHECK(t.height(o.x() - 2.0, o.y() + 1.0) == Approx(0.3));
    for (double x : {-1.0, 0.0, 2.5})
      CHECK((t.normal(x, 1.0) - fd_normal(t, x, 1.0)).norm() < 1e-8);
  }
  SECTION("bad parameters throw, naming the value") {
    CHECK_THROWS_WITH(slope_terrain(std::numbers::pi / 2), Contains("angle"));
    CHECK_THROWS_WITH(slope_terrain(kNaN), Contains("angle"));
    CHECK_THROWS_WITH(slope_terrain(0.1, kInf), Contains("height_at_origin"));
    CHECK_THROWS_WITH(slope_terrain(0.1, 0.0, Eigen::Vector2d::Zero()), Contains("direction"));
    CHECK_THROWS_WITH(slope_terrain(0.1, 0.0, Eigen::Vector2d(1, 0), Eigen::Vector2d(kNaN, 0)),
                      Contains("origin"));
  }
}

TEST_CASE("height_field_terrain: bilinear interpolation", "[contact][terrain][height_field]") {
  Eigen::MatrixXd h(4, 3);
  h << 0.0, 0.1, 0.2,   //
      0.3, -0.1, 0.05,  //
      0.15, 0.2, 0.0,   //
      0.4, 0.1, 0.3;
  const Eigen::Vector2d origin(-1.0, 2.0), spacing(0.5, 0.8);
  const height_field_terrain t(origin, spacing, h);
  REQUIRE(t.nx() == 4);
  REQUIRE(t.ny() == 3);

  SECTION("exact at the nodes") {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector2d p = t.node(i, j);
        CHECK(t.height(p.x(), p.y()) == Approx(h(i, j)).margin(1e-15));
      }
  }
  SECTION("linear along cell edges") {
    for (int i = 0; i + 1 < 4; ++i)
      for (int j = 0; j < 3; ++j)
        for (double s : {0.1, 0.37, 0.5, 0.9}) {
          const Eigen::Vector2d p = (1 - s) * t.node(i, j) + s * t.node(i + 1, j);
          CHECK(t.height(p.x(), p.y()) ==
                Approx((1 - s) * h(i, j) + s * h(i + 1, j)).margin(1e-14));
        }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j + 1 < 3; ++j)
        for (double s : {0.2, 0.5, 0.75}) {
          const Eigen::Vector2d p = (1 - s) * t.node(i, j) + s * t.node(i, j + 1);
          CHECK(t.height(p.x(), p.y()) ==
                Approx((1 - s) * h(i, j) + s * h(i, j + 1)).margin(1e-14));
        }
  }
  SECTION("bilinear in the cell interior: the centre is the corner mean") {
    const Eigen::Vector2d c = 0.5 * (t.node(1, 1) + t.node(2, 2));
    CHECK(t.height(c.x(), c.y()) == Approx(0.25 * (h(1, 1) + h(2, 1) + h(1, 2) + h(2, 2))));
  }
  SECTION("normal matches finite differences of the height inside cells") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> cu(0.05, 0.95);
    for (int k = 0; k < 200; ++k) {
      const int i = static_cast<int>(rng() % 3), j = static_cast<int>(rng() % 2);
      const double x = origin.x() + (i + cu(rng)) * spacing.x();
      const double y = origin.y() + (j + cu(rng)) * spacing.y();
      const vec3 n = t.normal(x, y);
      CHECK(n.norm() == Approx(1.0));
      CHECK(n.z() > 0.0);
      CHECK((n - fd_normal(t, x, y)).norm() < 1e-7);
    }
  }
  SECTION("outside the grid the query is clamped") {
    const Eigen::Vector2d last = t.node(3, 2);
    CHECK(t.height(last.x() + 10.0, last.y() + 5.0) == Approx(h(3, 2)));
    CHECK(t.height(origin.x() - 3.0, origin.y() - 1.0) == Approx(h(0, 0)));
    // Beyond the +x edge, the profile along y continues; the x-gradient is zero there.
    const double y = origin.y() + 0.5 * spacing.y();
    CHECK(t.height(last.x() + 2.0, y) == Approx(0.5 * (h(3, 0) + h(3, 1))));
    CHECK((t.normal(last.x() + 2.0, y) - fd_normal(t, last.x() + 2.0, y)).norm() < 1e-7);
    CHECK(t.gradient(last.x() + 2.0, y).x() == 0.0);
    CHECK(t.gradient(origin.x() - 1.0, origin.y() - 1.0).isZero());
  }
  SECTION("flat list constructor (x fastest) equals the matrix one") {
    std::vector<double> v;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) v.push_back(h(i, j));
    const height_field_terrain u(origin, spacing, 4, 3, v);
    CHECK(u.heights() == h);
  }
}

TEST_CASE("height_field_terrain: a single row is a planar profile", "[contact][terrain]") {
  Eigen::MatrixXd h(3, 1);
  h << 0.0, 0.2, 0.1;
  const height_field_terrain t(Eigen::Vector2d(0, 0), 1.0, h);
  for (double y : {-3.0, 0.0, 4.0}) {
    CHECK(t.height(0.5, y) == Approx(0.1));
    CHECK(t.height(1.25, y) == Approx(0.175));
  }
  CHECK((t.normal(0.5, 0.0) - vec3(-0.2, 0, 1).normalized()).norm() < 1e-14);
  CHECK(t.normal(0.5, 0.0).y() == 0.0);
}

TEST_CASE("height_field_terrain: bad input throws, naming the value", "[contact][terrain]") {
  const Eigen::Vector2d o(0, 0);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(2, 2);
  CHECK_THROWS_WITH(height_field_terrain(o, 0.0, h), Contains("spacing.x") && Contains("0"));
  CHECK_THROWS_WITH(height_field_terrain(o, Eigen::Vector2d(1.0, -2.0), h),
                    Contains("spacing.y") && Contains("-2"));
  CHECK_THROWS_WITH(height_field_terrain(o, kNaN, h), Contains("spacing"));
  CHECK_THROWS_WITH(height_field_terrain(Eigen::Vector2d(kInf, 0), 1.0, h), Contains("origin"));
  CHECK_THROWS_WITH(height_field_terrain(o, 1.0, Eigen::MatrixXd(0, 3)), Contains("empty"));
  Eigen::MatrixXd bad = h;
  bad(1, 0) = kNaN;
  CHECK_THROWS_WITH(height_field_terrain(o, 1.0, bad), Contains("node (1, 0)"));
  CHECK_THROWS_WITH(height_field_terrain(o, Eigen::Vector2d(1, 1), 2, 2, std::vector<double>(3)),
                    Contains("expected 4") && Contains("got 3"));
  CHECK_THROWS_WITH(height_field_terrain(o, Eigen::Vector2d(1, 1), 0, 2, {}), Contains("nx"));
}

TEST_CASE("random_height_field: seeded, reproducible, within range", "[contact][terrain]") {
  const random_height_field_options opt;  // Wu & Popovic: 1 m grid, heights in [0, 0.2] m
  const auto a = random_height_field(opt, 42);
  const auto b = random_height_field(opt, 42);
  const auto c = random_height_field(opt, 43);
  CHECK(a.heights() == b.heights());
  CHECK(a.heights() != c.heights());
  CHECK(a.nx() == opt.nx);
  CHECK(a.ny() == opt.ny);
  CHECK(a.spacing() == Eigen::Vector2d(1.0, 1.0));
  CHECK(a.heights().minCoeff() >= 0.0);
  CHECK(a.heights().maxCoeff() <= 0.2);
  // 561 independent U(0, 0.2) nodes: mean 0.1 with standard error 0.0024, spread near the bounds.
  CHECK(a.heights().mean() == Approx(0.1).margin(0.012));
  CHECK(a.heights().minCoeff() < 0.01);
  CHECK(a.heights().maxCoeff() > 0.19);
  // Every query lies in the range too (bilinear interpolation is a convex combination).
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> ux(-10, 50), uy(-8, 8);
  for (int k = 0; k < 1000; ++k) {
    const double hq = a.height(ux(rng), uy(rng));
    CHECK((hq >= 0.0 && hq <= 0.2));
  }
  random_height_field_options bad;
  bad.min_height = 0.25;
  CHECK_THROWS_WITH(random_height_field(bad, 1), Contains("min_height") && Contains("0.25"));
  bad = {};
  bad.spacing = -1.0;
  CHECK_THROWS_WITH(random_height_field(bad, 1), Contains("spacing"));
  bad = {};
  bad.ny = 0;
  CHECK_THROWS_WITH(random_height_field(bad, 1), Contains("ny"));
}

TEST_CASE("steps_terrain: stairs and drops along x", "[contact][terrain][steps]") {
  const steps_terrain t({{1.0, 0.1}, {1.3, 0.25}, {2.0, -0.05}}, 0.0);
  CHECK(t.height(0.99, 0.0) == 0.0);
  CHECK(t.height(1.0, 0.0) == 0.1);  // half-open: a step starts at its x_start
  CHECK(t.height(1.29, 5.0) == 0.1);
  CHECK(t.height(1.3, -5.0) == 0.25);
  CHECK(t.height(1.99, 0.0) == 0.25);
  CHECK(t.height(2.0, 0.0) == -0.05);
  CHECK(t.height(1e6, 0.0) == -0.05);
  CHECK(t.normal(1.5, 0.0) == vec3::UnitZ());

  const auto s = steps_terrain::stairs(0.5, 0.3, 0.17, 4);
  CHECK(s.height(0.4, 0) == 0.0);
  CHECK(s.height(0.55, 0) == Approx(0.17));
  CHECK(s.height(0.85, 0) == Approx(0.34));
  CHECK(s.height(1.45, 0) == Approx(0.68));
  CHECK(s.height(9.0, 0) == Approx(0.68));  // the landing continues
  const auto down = steps_terrain::stairs(0.0, 0.25, -0.1, 3, 1.0);
  CHECK(down.height(-1.0, 0) == 1.0);
  CHECK(down.height(0.6, 0) == Approx(0.7));
}

TEST_CASE("steps_terrain: penetration through the nearest face", "[contact][terrain][steps]") {
  // Ground 0 before x = 1, tread at 0.2 from x = 1 to 2, then 0.05.
  const steps_terrain t({{1.0, 0.2}, {2.0, 0.05}}, 0.0);
  SECTION("above the ground: no penetration") {
    CHECK(terrain_penetration(t, vec3(0.5, 0, 0.01)).depth < 0.0);
    CHECK(terrain_penetration(t, vec3(1.5, 0, 0.21)).depth < 0.0);
  }
  SECTION("slightly below a tread, far from its edges: pushed up") {
    const auto c = terrain_penetration(t, vec3(1.5, 0, 0.199));
    CHECK(c.depth == Approx(0.001));
    CHECK(c.normal == vec3::UnitZ());
  }
  SECTION("a toe running into the riser is pushed back, not lifted 0.2 m") {
    const auto c = terrain_penetration(t, vec3(1.004, 0, 0.05));
    CHECK(c.depth == Approx(0.004));
    CHECK(c.normal == -vec3::UnitX());
  }
  SECTION("descending: a point past the drop edge below the upper tread exits forward") {
    const auto c = terrain_penetration(t, vec3(1.997, 0.3, 0.1));
    CHECK(c.depth == Approx(0.003));
    CHECK(c.normal == vec3::UnitX());
  }
  SECTION("a riser buried by the next step is not an exit") {
    const steps_terrain u({{1.0, 0.2}, {1.01, 0.4}}, 0.0);
    // At x = 1.005, z = 0.1: the boundary at 1.01 leads to a 0.4 tread (above z): no exit there;
    // the riser at x = 1.0 is 0.005 away.
    const auto c = terrain_penetration(u, vec3(1.005, 0, 0.1));
    CHECK(c.depth == Approx(0.005));
    CHECK(c.normal == -vec3::UnitX());
    // At z = 0.3 (above the first tread), inside the second step: the exit is back over x = 1.01.
    const auto d = terrain_penetration(u, vec3(1.012, 0, 0.3));
    CHECK(d.depth == Approx(0.002));
    CHECK(d.normal == -vec3::UnitX());
  }
}

TEST_CASE("steps_terrain: penetration is the distance to the stair profile",
          "[contact][terrain][steps]") {
  // Brute force: the surface of a profile along x is its treads and risers (segments in x-z).
  const std::vector<steps_terrain::step> steps{{0.0, 0.15}, {0.3, 0.3}, {0.6, 0.1}, {0.65, 0.4}};
  const steps_terrain t(steps, 0.0);
  std::vector<std::array<double, 4>> seg;  // x0, z0, x1, z1
  double prev_h = 0.0, prev_x = -100.0;
  for (const auto& s : steps) {
    seg.push_back({prev_x, prev_h, s.x_start, prev_h});               // tread
    seg.push_back({s.x_start, std::min(prev_h, s.height), s.x_start,  // riser
                   std::max(prev_h, s.height)});
    prev_h = s.height;
    prev_x = s.x_start;
  }
  seg.push_back({prev_x, prev_h, 100.0, prev_h});
  const auto distance = [&](double x, double z) {
    double best = 1e300;
    for (const auto& g : seg) {
      const Eigen::Vector2d a(g[0], g[1]), b(g[2], g[3]), p(x, z);
      const double len2 = (b - a).squaredNorm();
      const double u = len2 > 0 ? std::clamp((p - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, (p - (a + u * (b - a))).norm());
    }
    return best;
  };
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ux(-0.2, 0.9), uz(-0.1, 0.45);
  int inside = 0;
  for (int k = 0; k < 2000; ++k) {
    const double x = ux(rng), z = uz(rng);
    const auto c = terrain_penetration(t, vec3(x, 0.0, z));
    if (z >= t.height(x, 0.0)) {
      CHECK(c.depth <= 0.0);
      continue;
    }
    ++inside;
    CHECK(c.depth == Approx(distance(x, z)).margin(1e-12));
    CHECK(c.normal.norm() == Approx(1.0));
    // Moving out along the normal by the depth lands on the surface (a profile point).
    const vec3 q = vec3(x, 0.0, z) + c.depth * c.normal;
    CHECK(distance(q.x(), q.z()) < 1e-12);
  }
  CHECK(inside > 500);
  // At the foot of a riser: pushed back and up toward the concave corner.
  const steps_terrain one({{1.0, 0.2}});
  const auto c = terrain_penetration(one, vec3(1.001, 0.0, -0.0003));
  CHECK(c.depth == Approx(std::hypot(0.001, 0.0003)));
  CHECK(c.normal.isApprox(vec3(-0.001, 0.0, 0.0003).normalized()));
}

TEST_CASE("steps_terrain: boxes and random boxes", "[contact][terrain][steps]") {
  Eigen::MatrixXd h(2, 2);
  h << 0.1, 0.0,  //
      0.2, 0.15;
  const auto t = steps_terrain::boxes(Eigen::Vector2d(0, 0), Eigen::Vector2d(1.0, 0.5), h, -0.1);
  CHECK(t.height(0.5, 0.25) == 0.1);
  CHECK(t.height(1.5, 0.25) == 0.2);
  CHECK(t.height(1.5, 0.75) == 0.15);
  CHECK(t.height(0.5, 0.75) == 0.0);
  CHECK(t.height(-0.5, 0.25) == -0.1);
  CHECK(t.height(0.5, 1.0) == -0.1);
  // Side face in y: the box (1, 1) at 0.15 next to box (1, 0) at 0.2; a point at z = 0.17 just
  // past y = 0.5 inside box (1,0)? No: y = 0.49 is in box (1, 0) (0.2); exit +y into box (1, 1).
  const auto c = terrain_penetration(t, vec3(1.5, 0.49, 0.17));
  CHECK(c.depth == Approx(0.01));
  CHECK(c.normal == vec3::UnitY());

  const random_boxes_options opt;
  const auto a = random_boxes(opt, 9), b = random_boxes(opt, 9), d = random_boxes(opt, 10);
  CHECK(a.heights() == b.heights());
  CHECK(a.heights() != d.heights());
  CHECK(a.heights().minCoeff() >= 0.0);
  CHECK(a.heights().maxCoeff() <= 0.2);
  CHECK(a.num_x() == 50);
  CHECK(a.height(-6.0, 0.0) == 0.0);
  CHECK(a.height(-4.5, -4.5) == a.heights()(0, 0));
}

TEST_CASE("steps_terrain: bad input throws, naming the value", "[contact][terrain][steps]") {
  CHECK_THROWS_WITH(steps_terrain(std::vector<steps_terrain::step>{}), Contains("empty"));
  CHECK_THROWS_WITH(steps_terrain({{1.0, 0.1}, {1.0, 0.2}}),
                    Contains("strictly increasing") && Contains("x_edges[1] = 1"));
  CHECK_THROWS_WITH(steps_terrain({{kNaN, 0.1}}), Contains("x_start"));
  CHECK_THROWS_WITH(steps_terrain({{0.0, kInf}}), Contains("step 0 height"));
  CHECK_THROWS_WITH(steps_terrain({{0.0, 0.1}}, kNaN), Contains("base_height"));
  CHECK_THROWS_WITH(steps_terrain::stairs(0.0, 0.0, 0.1, 3), Contains("run"));
  CHECK_THROWS_WITH(steps_terrain::stairs(0.0, 0.3, 0.1, 0), Contains("count"));
  CHECK_THROWS_WITH(steps_terrain({0.0, 1.0}, {0.0, 1.0, 2.0}, Eigen::MatrixXd::Zero(1, 1)),
                    Contains("heights cols") && Contains("expected 2") && Contains("got 1"));
  CHECK_THROWS_WITH(steps_terrain({0.0, kInf, 3.0}, {0.0, 1.0}, Eigen::MatrixXd::Zero(2, 1)),
                    Contains("x_edges[1]"));
  CHECK_THROWS_WITH(steps_terrain::boxes(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0),
                                         Eigen::MatrixXd::Zero(1, 1)),
                    Contains("size.y"));
  random_boxes_options bad;
  bad.max_height = kNaN;
  CHECK_THROWS_WITH(random_boxes(bad, 1), Contains("max_height"));
}
