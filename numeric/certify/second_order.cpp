// second_order(): certify on a converged polish, its verdict and reason as data.
#include "numeric/certify/second_order.hpp"

#include <stdexcept>

namespace scalcal {

SecondOrder second_order(const PolishResult& polished, CriterionKind criterion) {
  SecondOrder out;
  if (!polished.converged()) {
    out.text = "not checked (not converged)";
    return out;
  }
  if (polished.program.size() < 9) {
    out.text = "not checked (fewer than 9 positions)";
    return out;
  }
  try {
    const CertifyResult cert = certify(polished.program, criterion);
    out.status = cert.status;
    out.text = std::string(status_text(cert.status));
    out.reason = cert.reason;
  } catch (const std::invalid_argument& e) {
    out.text = "not checked";
    out.reason = e.what();
  }
  return out;
}

}  // namespace scalcal
