// Which weak-duality bound certifies a lower bound on a criterion's limit over a region
// (numeric/region/dual_certificate.hpp). A criterion that names none gets numerical limits only.
#pragma once

namespace scalcal {

enum class DualKind {
  None,
  Determinant,  // det M^-1 >= det W (P/m)^P for any W = C^T C > 0, m = sup h^T W h
  DiagonalSum,  // sum_r g_r K(r,r) >= (sum_r g_r c_r(r))^2 / sup sum_r (c_r . h)^2 (scaled rows)
  Spectral,     // lambda_max(M^-1) >= tr Z / sup h^T Z h for any Z = C^T C >= 0
};

}  // namespace scalcal
