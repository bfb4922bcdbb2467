# Precompiled headers: every unit parsed Eigen and the standard library again (and the front ends
# nlohmann-json, symbolic GiNaC, the tests GoogleTest), most of a small unit's compile time:
# commands/correct.cpp spent 7 s of its 8.5 s in -fsyntax-only. One header per target, private to
# it (nothing installed depends on it); -DSCALCAL_PCH=OFF turns them off.
option(SCALCAL_PCH "precompile the headers every unit of a target includes" ON)
set(SCALCAL_PCH_HEADERS <algorithm> <cmath> <cstdio> <functional> <iostream> <map> <memory> <optional>
    <sstream> <stdexcept> <string> <vector> <Eigen/Dense>)

# scalcal_precompile(TARGET [EXTRA_HEADER ...])
function(scalcal_precompile target)
  if(SCALCAL_PCH)
    target_precompile_headers(${target} PRIVATE ${SCALCAL_PCH_HEADERS} ${ARGN})
  endif()
endfunction()
