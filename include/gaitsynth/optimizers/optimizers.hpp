#pragma once
/// \file optimizers.hpp
/// All optimizer headers: parameter space, CMA-ES (+ IPOP/BIPOP restarts), SDS, evaluators,
/// the minimize driver (progress, CSV log, checkpoints), continuation.
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/continuation.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"
#include "gaitsynth/optimizers/restarts.hpp"
#include "gaitsynth/optimizers/sds.hpp"
