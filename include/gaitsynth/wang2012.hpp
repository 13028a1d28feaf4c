#pragma once
/// \file wang2012.hpp
/// Umbrella header of Wang, Hamner, Delp & Koltun 2012 (docs/reproductions/wang2012.md): the
/// 70 kg model with heel and ball cylinders, the Hill-type musculotendon actuator (Geyer & Herr
/// 2010 curves, eight MTUs per leg), the reflex controller with neural delays, the metabolic and
/// ablation efforts with the task terms, the search space and the muscle recordings.
/// gaitsynth.hpp holds the core they build on.
#include "gaitsynth/actuators/musculotendon/contraction.hpp"
#include "gaitsynth/actuators/musculotendon/hill_curves.hpp"
#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon/path.hpp"
#include "gaitsynth/actuators/musculotendon/unit.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/analysis/muscle_recording.hpp"
#include "gaitsynth/controllers/reflex/leg_phase.hpp"
#include "gaitsynth/controllers/reflex/reflex_laws.hpp"
#include "gaitsynth/controllers/reflex/reflex_parameters.hpp"
#include "gaitsynth/controllers/reflex/start_state_parameters.hpp"
#include "gaitsynth/controllers/reflex/upper_body_control.hpp"
#include "gaitsynth/controllers/reflex/upper_body_parameters.hpp"
#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/wang2012/effort_terms.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_rate.hpp"
#include "gaitsynth/objectives/wang2012/wang2012_objective.hpp"
#include "gaitsynth/synthesis/robust_variants.hpp"
#include "gaitsynth/synthesis/wang2012_search_space.hpp"
#if __has_include(<nlohmann/json.hpp>)
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#endif
