// A program's efficiency against a limit, the one definition every front end reports (the CLI, Python, the web
// page, whose WebAssembly core has no region code): limit / value, D as (limit / value)^(1/P) so that every
// efficiency reads as the fraction of the ideal measurement effort.
#pragma once
#include "numeric/criteria/registry.hpp"
#include "numeric/model/paper9.hpp"

namespace scalcal {

double efficiency(CriterionKind c, double limit, double value, int parameters = Paper9Model::kParameters);

}  // namespace scalcal
