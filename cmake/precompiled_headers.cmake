# Precompiled headers: every unit parsed Eigen and the standard library again (and the front ends
# nlohmann-json, symbolic GiNaC, the tests GoogleTest), most of a small unit's compile time:
# commands/calibration/correct.cpp spent 7 s of its 8.5 s in -fsyntax-only. One header per target, private to
# it (nothing installed depends on it); -DSCALCAL_PCH=OFF turns them off. Targets whose units are
# compiled with the same flags share one: building a header costs 3-7 s of CPU, and 26 targets
# each built their own (124 s of a whole build's CPU, 26 s of the CLI's).
option(SCALCAL_PCH "precompile the headers every unit of a target includes" ON)
set(SCALCAL_PCH_HEADERS <algorithm> <cmath> <cstdio> <functional> <iostream> <map> <memory> <optional>
    <sstream> <stdexcept> <string> <vector> <Eigen/Dense>)

# scalcal_precompile(TARGET [EXTRA_HEADER ...])
function(scalcal_precompile target)
  if(SCALCAL_PCH)
    target_precompile_headers(${target} PRIVATE ${SCALCAL_PCH_HEADERS} ${ARGN})
  endif()
endfunction()

# scalcal_share_precompiled(TARGET OWNER): TARGET's units include OWNER's precompiled header (built
# by scalcal_precompile) instead of one of their own. OWNER's units must be compiled with the same
# optimisation and code-generation flags (clang refuses the header otherwise); macros defined on
# the command line may differ.
function(scalcal_share_precompiled target owner)
  if(SCALCAL_PCH)
    target_precompile_headers(${target} REUSE_FROM ${owner})
  endif()
endfunction()

# scalcal_precompile_in_group(GROUP TARGET [EXTRA_HEADER ...]): the first target of GROUP builds the
# header (scalcal_precompile), every later one shares it (scalcal_share_precompiled).
function(scalcal_precompile_in_group group target)
  get_property(owner GLOBAL PROPERTY SCALCAL_PCH_OWNER_${group})
  if(owner)
    scalcal_share_precompiled(${target} ${owner})
  else()
    scalcal_precompile(${target} ${ARGN})
    set_property(GLOBAL PROPERTY SCALCAL_PCH_OWNER_${group} ${target})
  endif()
endfunction()
