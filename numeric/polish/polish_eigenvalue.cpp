// The eigenvalue-form polish (E) of the paper's model, in MPFR: compiled here once.
#include "numeric/polish/polish_eigenvalue.hpp"

namespace scalcal::polish_detail {

template PolishResult polish_eigenvalue<Paper9Model>(const PolishOps<Paper9Model>&, const Program&,
                                                     const PolishOptions&);

}  // namespace scalcal::polish_detail
