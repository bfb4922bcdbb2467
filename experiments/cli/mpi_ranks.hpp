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
  // Every rank's text, in rank order, on every rank.
  std::vector<std::string> all_gather(const std::string& text) const;
  // A counter shared by the ranks: each call returns the next value (0, 1, 2, ...) to whichever rank
  // asks first, so the ranks take tasks as they free up instead of in a fixed round (one atomic
  // fetch-and-add on rank 0's memory, MPI_Fetch_and_op; a plain counter in one process). Collective:
  // every rank opens it, and every rank must close it (close_counter) before gathering.
  void open_counter();
  long long next() const;
  void close_counter();
  ~Ranks();

 private:
  Ranks();
  int rank_ = 0, size_ = 1;
  bool initialised_ = false;
  mutable long long local_next_ = 0;  // the counter in one process
  void* window_ = nullptr;            // MPI_Win of the shared counter (an MPI_Win is a handle)
  long long* counter_ = nullptr;      // rank 0's counter, in the window
};

}  // namespace scalcal::cli
