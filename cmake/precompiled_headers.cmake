# Precompiled headers: every unit parsed Eigen and the standard library again (and the front ends
# nlohmann-json, symbolic GiNaC, the tests GoogleTest), most of a small unit's compile time:
# commands/calibration/correct.cpp spent 7 s of its 8.5 s in -fsyntax-only. One header per target, private to
# it (nothing installed depends on it); -DSCALCAL_PCH=OFF turns them off. Targets whose units are
# compiled with the same flags share one: building a header costs 3-7 s of CPU, and 26 targets
# each built their own (124 s of a whole build's CPU, 26 s of the CLI's).
option(SCALCAL_PCH "precompile the headers every unit of a target includes" ON)
set(SCALCAL_PCH_HEADERS <algorithm> <cmath> <cstdio> <functional> <iostream> <map> <memory> <optional>
    <sstream> <stdexcept> <string> <vector> <Eigen/Dense>)
# And the project's headers that most units include (the model and criterion registries, with the Eigen
# decompositions dense_instances.hpp declares extern, and the program): a class template they instantiate, such
# as the four eigen-solvers the extern declarations need whole, is then instantiated once in the header instead
# of in each of some 200 units (55 CPU-s of the CLI's build, docs/benchmarks.md). What is in the header every
# unit of its target sees, so a unit that forgets to include one of these still compiles here:
# -DSCALCAL_PCH_PROJECT=OFF leaves them out, as the build without GiNaC does (scripts/without_ginac.sh), where such
# a unit fails.
option(SCALCAL_PCH_PROJECT "precompile the project's most included headers too (with SCALCAL_PCH)" ON)
set(SCALCAL_PCH_PROJECT_HEADERS "")
if(SCALCAL_PCH_PROJECT)
  set(SCALCAL_PCH_PROJECT_HEADERS [["numeric/model/registry.hpp"]] [["numeric/criteria/registry.hpp"]]
      [["numeric/program/program.hpp"]])
endif()

# scalcal_precompile(TARGET [EXTRA_HEADER ...])
function(scalcal_precompile target)
  if(SCALCAL_PCH)
    target_precompile_headers(${target} PRIVATE ${SCALCAL_PCH_HEADERS} ${SCALCAL_PCH_PROJECT_HEADERS} ${ARGN})
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
