// The Ipopt application every local solve in this process shares (one per thread, created once):
// quiet, adaptive barrier, no forced iterative refinement. Callers set their own tolerances.
#pragma once
#include <IpIpoptApplication.hpp>

namespace scalcal {

// Null when Ipopt cannot be initialised.
Ipopt::SmartPtr<Ipopt::IpoptApplication> ipopt_application();

}  // namespace scalcal
