#pragma once
/// \file models.hpp
/// All built-in characters (docs/models.md):
///   sharon2005_human7(params)      7-link planar human, Sharon & van de Panne 2005, Table I
///   sharon2005_human16(params)     16-link planar human (de Leva 1996 segments)
///   wang2009_humanoid(body|shape)  30-DOF humanoid, Wang et al. 2009, Fig. 8 presets
///   wu2010_biped()                 Table 3 biped, Wu & Popovic 2010
///   wang2012_humanoid()            180 cm / 70 kg humanoid, Wang et al. 2012
/// the de Leva 1996 segment table (anthropometry.hpp) and the helpers standing_configuration(),
/// standing_height(), neutral_body_origins() (standing.hpp).
#include "gaitsynth/models/anthropometry.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/models/wu2010.hpp"
