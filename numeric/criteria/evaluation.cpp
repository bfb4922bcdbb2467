#include "numeric/criteria/evaluation.hpp"

namespace scalcal {

template EvaluationTpl<double, Paper9Model> evaluate<Paper9Model, double>(const ProgramTpl<double>&);

}  // namespace scalcal
