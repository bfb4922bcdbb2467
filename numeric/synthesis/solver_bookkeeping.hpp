// Bookkeeping that Debian's MUMPS 5.5 and Ipopt 3.11 do on every call and scalcal never reads,
// replaced by definitions that skip it (solver_bookkeeping.cpp says what and why).
#pragma once

namespace scalcal {

// Whether the process's global symbols resolve the replaced functions to scalcal's, as in every
// executable that links scalcal: false where one does not export them (the solvers then run their
// own, only slower). A Python module is loaded with local symbols, where MUMPS and Ipopt still find
// the module's first (a profile of its E at N = 9 has no sample in them) but this cannot tell.
bool solver_bookkeeping_replaced();

}  // namespace scalcal
