// The process group a command runs in: one process (the default), or the ranks of an MPI job when
// scalcal was started by mpirun and built with MPI (SCALCAL_HAVE_MPI). Only `sweep` spreads work;
// MPI is initialised on first use and finalised at exit.
#pragma once
#include <string>
#include <vector>

namespace scalcal::cli {

class Ranks {
 public:
  static Ranks& world();
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Every rank's text, in rank order, on rank 0; an empty vector elsewhere.
  std::vector<std::string> gather(const std::string& text) const;
  ~Ranks();

 private:
  Ranks();
  int rank_ = 0, size_ = 1;
  bool initialised_ = false;
};

}  // namespace scalcal::cli
