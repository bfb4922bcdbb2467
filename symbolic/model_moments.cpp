// The paper's model states no exponent table (its row is written out in numeric/model/paper9.hpp),
// so its table is given here; tests check it against design_row for every family.
#include "symbolic/model_moments.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>

namespace scalcal::symbolic {

std::optional<std::vector<std::array<int, 3>>> model_exponents(ModelKind model) {
  return visit_model(model, [](auto M) -> std::optional<std::vector<std::array<int, 3>>> {
    using Model = decltype(M);
    if constexpr (requires { Model::exponents; }) {
      return std::vector<std::array<int, 3>>(Model::exponents.begin(), Model::exponents.end());
    } else if constexpr (std::is_same_v<Model, Paper9Model>) {
      return std::vector<std::array<int, 3>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0},
                                             {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    } else {
      return std::nullopt;
    }
  });
}

std::vector<ParameterGroup> model_groups(ModelKind model) {
  return visit_model(model, [](auto M) {
    using Model = decltype(M);
    return std::vector<ParameterGroup>(Model::parameter_groups.begin(), Model::parameter_groups.end());
  });
}

GiNaC::matrix model_moment_matrix(ModelKind model, const MomentFunction& moment) {
  const auto expo = model_exponents(model);
  if (!expo) throw std::invalid_argument("model " + std::string(model_name(model)) + " has no table of monomials");
  const unsigned P = static_cast<unsigned>(expo->size());
  GiNaC::matrix M(P, P);
  for (unsigned r = 0; r < P; ++r)
    for (unsigned c = r; c < P; ++c) {
      const auto& a = (*expo)[r];
      const auto& b = (*expo)[c];
      M(r, c) = M(c, r) = moment(a[0] + b[0], a[1] + b[1], a[2] + b[2]);
    }
  return M;
}

}  // namespace scalcal::symbolic
