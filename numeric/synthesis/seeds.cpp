// The seeds of every random choice, from splitmix64 (seeds.hpp).
#include "numeric/synthesis/seeds.hpp"

#include <thread>

namespace scalcal {

int thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

}  // namespace scalcal
