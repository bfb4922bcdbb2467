// The KKT polish (smooth and max-diagonal forms) of the paper's model, in MPFR: compiled here once.
#include "numeric/polish/polish_kkt.hpp"

namespace scalcal::polish_detail {

template PolishResult polish_kkt<Paper9Model>(const PolishOps<Paper9Model>&, const Program&, const PolishOptions&);

}  // namespace scalcal::polish_detail
