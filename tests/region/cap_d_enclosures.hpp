// The D limits of the 30, 60, 90 and 120-degree caps as proofs/checks/cap_d_limit.cpp encloses them in exact
// rational arithmetic (lower ends, 36 digits; relative width 1.8e-44): what the zonal solver and the closed
// form are both checked against.
#pragma once

namespace scalcal::testing {

struct CapDEnclosure {
  double deg, exact;
};

inline constexpr CapDEnclosure kCapDEnclosures[] = {{30, 1.02240851106493129379295952002523676e+23},
                                                    {60, 2.10863441696092520602537447015586759e+13},
                                                    {90, 9.39809328436720974260809992031664894e+08},
                                                    {120, 2.16835955359789343745625399524988806e+07}};

}  // namespace scalcal::testing
