// The paper's model plus a scale factor that varies linearly with the input on each axis
// (y_i = (1 + s_i + k_i a_i) a_i + ...), so the scalar model gains x^3, y^3, z^3: 12 parameters,
// moments up to degree 6. Its optimal measures live on the 6 axis and 8 cube-diagonal directions
// only, each unique, with weights that need N = 132k for D, 624k for E, 48k for S and no N at all
// for A (proofs/cubic12_limits.md).
#pragma once
#include "numeric/model/cubic_meter.hpp"
#include "numeric/model/model_limit.hpp"
#include "numeric/model/monomial_model.hpp"

namespace scalcal {

struct Cubic12Model : MonomialModel<Cubic12Model> {
  static constexpr int kParameters = 12;
  static constexpr std::string_view name = "cubic12";
  using meter = CubicMeter;  // its parameters are this meter's, by name
  static constexpr std::string_view summary = "paper9 plus (x^3, y^3, z^3): a scale factor linear in the input";
  // What a fit under this model leaves out beyond the rotation no scalar calibration sees (calibrate's report).
  static constexpr std::string_view not_estimated =
      "at one magnitude the cubic term is identified as c_i |I| only (it cannot be told from a scale factor that "
      "depends on the magnitude), and never from positions along the axes alone, where x^3 = x makes it the bias";
  static constexpr std::array<std::string_view, 12> parameter_names = {
      "bias_x",     "bias_y",     "bias_z",     "scale_x", "scale_y", "scale_z",
      "nonorth_xy", "nonorth_yz", "nonorth_zx", "cubic_x", "cubic_y", "cubic_z"};
  static constexpr std::array<ParameterGroup, 12> parameter_groups = {
      ParameterGroup::bias,    ParameterGroup::bias,  ParameterGroup::bias,    ParameterGroup::scale,
      ParameterGroup::scale,   ParameterGroup::scale, ParameterGroup::nonorth, ParameterGroup::nonorth,
      ParameterGroup::nonorth, ParameterGroup::cubic, ParameterGroup::cubic,   ParameterGroup::cubic};
  static constexpr std::array<Exponents, 12> exponents = {{{1, 0, 0},
                                                           {0, 1, 0},
                                                           {0, 0, 1},
                                                           {2, 0, 0},
                                                           {0, 2, 0},
                                                           {0, 0, 2},
                                                           {1, 1, 0},
                                                           {0, 1, 1},
                                                           {1, 0, 1},
                                                           {3, 0, 0},
                                                           {0, 3, 0},
                                                           {0, 0, 3}}};

  static constexpr std::string_view proof = "proofs/cubic12_limits.md";
  // Weight lambda on the six axis directions, 1 - lambda on the eight cube diagonals (+-1,+-1,+-1)/sqrt 3:
  // E[x^4] = (1 + 2 lambda)/9, E[x^2 y^2] = (1 - lambda)/9, E[x^6] = (1 + 8 lambda)/27.
  static constexpr std::array<ModelLimit, 4> limits = {{
      {"D", 4093910627611872177.0 / 12800000.0, "4093910627611872177/12800000", "7/33", "2/33", "17/99", 2.0 / 33,
       "weight 5/11 on the 6 axis directions, 6/11 on the 8 cube diagonals",
       "exactly N = 132k (5/66 and 3/44 of N per direction): none below 132 (proven)", 5.0 / 11},
      {"A", 186.72114910328065, "99+9*sqrt(95)", "(3*sqrt(95)-6)/117", "(45-3*sqrt(95))/234", "(4*sqrt(95)-21)/117",
       0.06734879045116712, "weight (3 sqrt 95 - 19)/26 on the 6 axis directions, the rest on the 8 cube diagonals",
       "no finite N: the optimal weights are irrational (proven)", 0.3938608859394958 /* (3 sqrt 95 - 19)/26 */},
      {"E", 39.0, "39", "8/39", "5/78", "19/117", 5.0 / 78,
       "weight 11/26 on the 6 axis directions, 15/26 on the 8 cube diagonals",
       "exactly N = 624k (44 per axis direction, 45 per cube diagonal, times k) (proven)", 11.0 / 26},
      {"S", 27.0, "27", "2/9", "1/18", "5/27", 1.0 / 18,
       "weight 1/2 on the 6 axis directions, 1/2 on the 8 cube diagonals",
       "exactly N = 48k (4 per axis direction, 3 per cube diagonal, times k) (proven)", 0.5,
       // Randomised roundings as starts: 12 of them at N = 49, 61, 150 reached 27.0982, 27.0829, 27.0369
       // in 0.1-0.3 s each, where 69, 81 and 170 random starts (2-9 s each) reached 27.1072, 27.0829 and
       // no better than the first rounding's 27.0433.
       true},
  }};
};
static_assert(CalibrationModel<Cubic12Model>);

}  // namespace scalcal
