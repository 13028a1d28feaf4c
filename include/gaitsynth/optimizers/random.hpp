#pragma once
/// \file random.hpp
/// Random variates for the optimizers, drawn from an explicitly seeded std::mt19937_64.
///
/// Why not std::uniform_real_distribution / std::normal_distribution: their algorithms are left to
/// the standard library (results differ between libstdc++ and libc++) and normal_distribution
/// caches a second variate, which would have to be checkpointed too. The functions
/// (detail/uniform01.hpp, detail/standard_normal.hpp, shared with the seeded start perturbations of
/// rollout/) are stateless given the engine, so the engine's state (which the standard lets us
/// write and read back exactly) is the whole random state of an optimizer. Seed 0 is an ordinary
/// seed.
#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <random>

#include "gaitsynth/detail/standard_normal.hpp"
#include "gaitsynth/detail/uniform01.hpp"
