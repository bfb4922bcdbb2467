// The evaluation of a program of the paper's model in MPFR (the SVD of H at the polish's working
// precision), which both polish forms read the polished value from: compiled here once.
#include "numeric/polish/polish_ops.hpp"

namespace scalcal {

template EvaluationTpl<polish_detail::Real, Paper9Model> evaluate<Paper9Model, polish_detail::Real>(
    const ProgramTpl<polish_detail::Real>&);

}  // namespace scalcal
