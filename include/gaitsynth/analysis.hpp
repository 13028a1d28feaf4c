#pragma once
/// \file analysis.hpp
/// Umbrella header of the gait measures (used by docs/reproductions/wang2009.md and wang2012.md):
/// gait cycles and their windows, sagittal features, ankle push-off against the human data, arm
/// swing, torso lean, standard scores against normative data, muscle recordings, swing clearance.
#include "gaitsynth/analysis/ankle_push_off.hpp"
#include "gaitsynth/analysis/arm_swing.hpp"
#include "gaitsynth/analysis/cycle_window.hpp"
#include "gaitsynth/analysis/human_ankle_push_off.hpp"
#include "gaitsynth/analysis/muscle_recording.hpp"
#include "gaitsynth/analysis/sagittal_gait_features.hpp"
#include "gaitsynth/analysis/standard_score.hpp"
#include "gaitsynth/analysis/swing_clearance.hpp"
#include "gaitsynth/analysis/torso_lean.hpp"
