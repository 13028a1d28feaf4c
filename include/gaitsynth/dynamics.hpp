#pragma once
/// \file dynamics.hpp
/// Umbrella header of the rigid-body dynamics module (docs/dynamics.md).
#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/dynamics/energy.hpp"
#include "gaitsynth/dynamics/jacobian.hpp"
#include "gaitsynth/dynamics/joint_limits.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/momentum.hpp"
#include "gaitsynth/dynamics/rnea.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/spatial/spatial.hpp"
