// The process group of a command: one process, or the ranks of an MPI job (mpi_ranks.hpp).
#include "experiments/cli/mpi_ranks.hpp"

#include <cstdlib>

#ifdef SCALCAL_HAVE_MPI
#include <mpi.h>
#endif

// Every call goes through the profiling names (PMPI_*): Debian's sequential MUMPS, which Ipopt loads
// before libmpi, exports a dummy C MPI_Init, MPI_Comm_rank and MPI_Finalize that would shadow the real
// ones (MPI_Init would reach MUMPS's stub and the next real call would abort the job).
namespace scalcal::cli {
namespace {

// mpirun (Open MPI, MPICH/Hydra, Slurm's PMI/PMIx) sets one of these; a plain run never calls MPI.
bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

#ifdef SCALCAL_HAVE_MPI
// Where each rank's text starts in the gathered text, the total last (one entry, 0, for no rank: a rank
// that receives nothing).
std::vector<int> offsets_of(const std::vector<int>& lengths) {
  std::vector<int> at(lengths.size() + 1, 0);
  for (std::size_t r = 0; r < lengths.size(); ++r) at[r + 1] = at[r] + lengths[r];
  return at;
}

// The gathered text cut back into each rank's.
std::vector<std::string> pieces(const std::string& all, const std::vector<int>& offsets) {
  std::vector<std::string> out;
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
    out.push_back(all.substr(offsets[r], offsets[r + 1] - offsets[r]));
  return out;
}
#endif

}  // namespace

Ranks& Ranks::world() {
  static Ranks ranks;
  return ranks;
}

Ranks::Ranks() {
#ifdef SCALCAL_HAVE_MPI
  if (!launched_by_mpirun()) return;
  PMPI_Init(nullptr, nullptr);
  initialised_ = true;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  PMPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
  (void)launched_by_mpirun;
#endif
}

Ranks::~Ranks() {
#ifdef SCALCAL_HAVE_MPI
  if (initialised_) PMPI_Finalize();
#endif
}

std::vector<std::string> Ranks::gather(const std::string& text) const {
  if (size_ == 1) return {text};
#ifdef SCALCAL_HAVE_MPI
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(rank_ == 0 ? size_ : 0);
  PMPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets = offsets_of(lengths);
  std::string all(static_cast<std::size_t>(offsets.back()), '\0');
  PMPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  return pieces(all, offsets);
#else
  return {text};
#endif
}

std::vector<std::string> Ranks::all_gather(const std::string& text) const {
  if (size_ == 1) return {text};
#ifdef SCALCAL_HAVE_MPI
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(size_);
  PMPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<int> offsets = offsets_of(lengths);
  std::string all(static_cast<std::size_t>(offsets.back()), '\0');
  PMPI_Allgatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, MPI_COMM_WORLD);
  return pieces(all, offsets);
#else
  return {text};
#endif
}

void Ranks::open_counter() {
  local_next_ = 0;
#ifdef SCALCAL_HAVE_MPI
  if (size_ == 1) return;
  MPI_Win* win = new MPI_Win;
  PMPI_Win_allocate(rank_ == 0 ? static_cast<MPI_Aint>(sizeof(long long)) : 0, sizeof(long long), MPI_INFO_NULL,
                    MPI_COMM_WORLD, &counter_, win);
  if (rank_ == 0) {
    PMPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, *win);
    *counter_ = 0;
    PMPI_Win_unlock(0, *win);
  }
  window_ = win;
  PMPI_Barrier(MPI_COMM_WORLD);  // no rank takes a value before rank 0 set the counter
#endif
}

long long Ranks::next() const {
#ifdef SCALCAL_HAVE_MPI
  if (window_) {
    const MPI_Win win = *static_cast<MPI_Win*>(window_);
    const long long one = 1;
    long long value = 0;
    PMPI_Win_lock(MPI_LOCK_SHARED, 0, 0, win);
    PMPI_Fetch_and_op(&one, &value, MPI_LONG_LONG, 0, 0, MPI_SUM, win);
    PMPI_Win_unlock(0, win);
    return value;
  }
#endif
  return local_next_++;
}

void Ranks::close_counter() {
#ifdef SCALCAL_HAVE_MPI
  if (!window_) return;
  MPI_Win* win = static_cast<MPI_Win*>(window_);
  PMPI_Win_free(win);
  delete win;
  window_ = nullptr;
  counter_ = nullptr;
#endif
}

}  // namespace scalcal::cli
