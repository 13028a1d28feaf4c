#pragma once
/// \file models.hpp
/// All built-in characters (docs/models.md):
///   sharon2005_human7(), sharon2005_human16()        planar humans of Sharon & van de Panne 2005
///   wang2009_humanoid(body / shape)                   30-DOF humanoid of Wang et al. 2009, Fig. 8
/// and the helpers standing_configuration(), standing_height().
#include "gaitsynth/models/anthropometry.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"
