#include "study/mpi_session.hpp"

#include <cstdlib>
#include <string>

#include "core/error.hpp"

#ifdef ROLLNOISE_HAVE_MPI
#include <mpi.h>
#endif

namespace rollnoise {
namespace {

// Set by OpenMPI's launcher (and by PMIx-based ones) in every rank it starts.
bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace

int ranks_from_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* value = std::getenv(name);
    if (!value) continue;
    char* end = nullptr;
    const long ranks = std::strtol(value, &end, 10);
    if (end != value && *end == '\0' && ranks >= 1 && ranks <= 1 << 24) return static_cast<int>(ranks);
  }
  return 1;
}

std::string mpi_launch_problem(bool built_with_mpi, int launched_ranks) {
  if (built_with_mpi || launched_ranks <= 1) return "";
  return "this rollnoise was built without MPI (libopenmpi-dev was missing when it was built, or "
         "-DROLLNOISE_MPI=OFF), so each of the " + std::to_string(launched_ranks) +
         " ranks would run the whole study into the same folder; rebuild with MPI (bash tools/setup.sh "
         "installs it), or run without mpirun (--threads N uses the cores of one machine)";
}

bool MpiSession::built_with_mpi() noexcept {
#ifdef ROLLNOISE_HAVE_MPI
  return true;
#else
  return false;
#endif
}

MpiSession::MpiSession() {
  if (const std::string problem = mpi_launch_problem(built_with_mpi(), ranks_from_launcher()); !problem.empty())
    throw InputError("command line", "mpirun", problem);
#ifdef ROLLNOISE_HAVE_MPI
  if (!launched_by_mpirun()) return;
  int provided = 0;
  // Only the main thread calls MPI; the case threads never do.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  if (node != MPI_COMM_NULL) {
    MPI_Comm_size(node, &ranks_on_node_);
    MPI_Comm_free(&node);
  }
#endif
}

MpiSession::~MpiSession() {
#ifdef ROLLNOISE_HAVE_MPI
  if (active_ && finalize_) MPI_Finalize();
#endif
}

void MpiSession::barrier() const {
#ifdef ROLLNOISE_HAVE_MPI
  if (active_) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

int MpiSession::max_over_ranks(int value) const {
#ifdef ROLLNOISE_HAVE_MPI
  if (active_) {
    int largest = value;
    MPI_Allreduce(&value, &largest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return largest;
  }
#endif
  return value;
}

std::vector<std::string> MpiSession::gather(const std::string& text) const {
#ifdef ROLLNOISE_HAVE_MPI
  if (active_) {
    int length = static_cast<int>(text.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_));
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(static_cast<std::size_t>(size_), 0);
    int total = 0;
    for (int r = 0; r < size_; ++r) {
      offsets[static_cast<std::size_t>(r)] = total;
      total += lengths[static_cast<std::size_t>(r)];
    }
    std::string all(static_cast<std::size_t>(rank_ == 0 ? total : 0), '\0');
    MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
    std::vector<std::string> out;
    if (rank_ == 0)
      for (int r = 0; r < size_; ++r)
        out.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                                 static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
    return out;
  }
#endif
  return {text};
}

}  // namespace rollnoise
