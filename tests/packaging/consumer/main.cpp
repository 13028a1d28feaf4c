// A tiny project that uses an installed gaitsynth through find_package(gaitsynth CONFIG REQUIRED).
#include <gaitsynth/model/model_builder.hpp>
#include <gaitsynth/model/state.hpp>
#include <iostream>

int main() {
  gaitsynth::model_builder<gaitsynth::planar_root> b("pendulum");
  b.add_body({.name = "base", .mass = 1.0, .inertia = Eigen::Matrix3d::Identity() * 0.01});
  b.add_body({.name = "link",
              .parent = "base",
              .mass = 2.0,
              .com = {0, 0, -0.5},
              .inertia = Eigen::Matrix3d::Identity() * 0.02,
              .dofs = {{.name = "hinge"}}});
  const auto m = b.build();
  const auto s = gaitsynth::make_state(m);
  if (m.nq() != 4 || s.v.size() != 4) return 1;
  std::cout << "gaitsynth consumer ok: " << m.name << " nq=" << m.nq() << "\n";
  return 0;
}
