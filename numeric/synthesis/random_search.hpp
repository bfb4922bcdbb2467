// The best of R programs uniform on the sphere (the paper's dashed line): a fixed-size hot loop
// (random_search_kernel.hpp) on all cores; the same seed gives the same answer on any thread count.
#pragma once
#include <cstdint>
#include <functional>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

struct RandomSearchResult {
  Program program;  // the best of `count` random programs
  double best = 0;
  long long count = 0;
  double seconds = 0;
};

class Xoshiro256x4;

// Draws n positions into x, y, z (each with room for sample_buffer_size(n) of
// random_search_kernel.hpp, zero past n) from the generator: how the random programs of a
// restricted bench are made (numeric/region/region_sampler.hpp). Empty: uniform on the sphere.
using PositionSampler = std::function<void(Xoshiro256x4& rng, int n, double* x, double* y, double* z)>;

// Throws std::invalid_argument when positions < P (the model's parameters) or count < 1. The
// paper's model runs the fixed 9x9 kernel; any other model draws the same programs (same seed, same
// positions) and scores each from its own P x P information matrix.
RandomSearchResult random_search(int positions, long long count, CriterionKind criterion, std::uint64_t seed,
                                 int threads = 0, const PositionSampler& sampler = {},
                                 ModelKind model = ModelKind::paper9);

}  // namespace scalcal
