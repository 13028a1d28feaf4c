#pragma once
// moved; kept for existing includes
#include "gaitsynth/motion/keyframes_json.hpp"
