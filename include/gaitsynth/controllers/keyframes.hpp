#pragma once
// moved; kept for existing includes
#include "gaitsynth/motion/keyframes.hpp"
