#pragma once
// design::DesignExplanation (design/explanation.h) and its parts as LCM messages (explanation_t
// and the types it holds), for design_result_t.

#include "design/design_explanation.h"
#include "envdesign/design_terms_t.hpp"
#include "envdesign/explanation_t.hpp"
#include "envdesign/task_result_t.hpp"

namespace envdesign::wire {

envdesign::design_terms_t terms_message(const design::Objective &objective);
// Task `i` of `problem`; in EXPLAINING mode with the option the robot takes.
envdesign::task_result_t task_message(const design::DesignProblem &problem, int i,
                                      const design::TaskExplicability &evaluation);
// The point with its objective and terms at the problem's weights.
envdesign::design_point_t point_message(const design::DesignProblem &problem,
                                        const design::DesignPoint &point);
envdesign::explanation_t explanation_message(const design::DesignProblem &problem,
                                             const design::DesignExplanation &explanation);
// An explanation_t with every field set (sent when there is none: has_explanation false).
envdesign::explanation_t empty_explanation();

} // namespace envdesign::wire
