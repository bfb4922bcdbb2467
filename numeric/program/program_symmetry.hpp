// The group under which two programs count as the same program (each criterion names its own).
#pragma once

namespace scalcal {

// The group under which a criterion is invariant, which decides when two optimal programs are the
// same program: O(3) for D (det K moves by det(g)^2 = 1), the 48 signed permutations of the axes for
// criteria of single entries or of the spectrum of K in the paper's basis.
enum class ProgramSymmetry { SignedPermutations, Orthogonal };

}  // namespace scalcal
