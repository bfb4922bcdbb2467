// The sentences that explain a rank-deficient or ill-conditioned program (identifiability.hpp).
#include "numeric/criteria/identifiability.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

namespace scalcal {

std::string rank_deficiency(const Evaluation& ev) { return rank_deficiency(erase_model(ev)); }
std::string ill_conditioning(const Evaluation& ev) { return ill_conditioning(erase_model(ev)); }

std::string rank_deficiency(const ModelEvaluation& ev) {
  std::string s = "rank-deficient program: rank " + std::to_string(ev.rank) + " of " + std::to_string(ev.parameters);
  if (!ev.unidentifiable.empty()) {
    s += "; not identifiable:";
    for (std::size_t k = 0; k < ev.unidentifiable.size(); ++k)
      s += (k ? ", " : " ") + std::string(ev.parameter_names[static_cast<std::size_t>(ev.unidentifiable[k])]);
  }
  return s;
}

std::string ill_conditioning(const ModelEvaluation& ev) {
  // The eigenvector of the smallest eigenvalue of H^T H is the worst-determined combination.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(ev.information);
  const Eigen::VectorXd v = eig.eigenvectors().col(0);
  std::ostringstream s;
  s << "ill-conditioned program (condition " << ev.condition << "): the combination poorly determined is mostly";
  bool first = true;
  for (int r = 0; r < ev.parameters; ++r)
    if (std::abs(v(r)) > 0.3) {
      s << (first ? " " : ", ") << ev.parameter_names[static_cast<std::size_t>(r)];
      first = false;
    }
  return s.str();
}

}  // namespace scalcal
