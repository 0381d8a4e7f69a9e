#pragma once
// The ranks a study runs on: under `mpirun` (OpenMPI), every rank of MPI_COMM_WORLD; otherwise
// (or when built without MPI) a single rank. MPI is started only when the program was launched
// by mpirun, so the same binary runs locally without it.
#include <string>
#include <vector>

namespace rollnoise {

// The ranks a launcher (mpirun, srun with PMI) says this process is one of: 1 when none did.
int ranks_from_launcher();

// Why a process cannot run as one of `launched_ranks` ranks ("" when it can): a build without
// MPI under `mpirun -n N` would run N whole copies of a study into one folder.
std::string mpi_launch_problem(bool built_with_mpi, int launched_ranks);

class MpiSession {
 public:
  // InputError when launched as several ranks by a build without MPI (mpi_launch_problem).
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const noexcept { return rank_; }
  int size() const noexcept { return size_; }
  // The ranks that share this rank's machine (MPI_COMM_TYPE_SHARED), this one included: the
  // machine's cores are theirs together. 1 without MPI.
  int ranks_on_node() const noexcept { return ranks_on_node_; }
  bool active() const noexcept { return active_; }
  // Whether this build can run under MPI at all.
  static bool built_with_mpi() noexcept;

  void barrier() const;
  // The largest of every rank's `value`, on every rank (each rank must call it).
  int max_over_ranks(int value) const;
  // Every rank's `text`, on rank 0 (in rank order); empty on the others.
  std::vector<std::string> gather(const std::string& text) const;
  // Leave MPI without MPI_Finalize at the end, for a run stopped by a signal: mpirun turns a
  // Ctrl-C into SIGTERM to every rank and tears the job down, and MPI_Finalize's handshake with
  // it then never completes (the rank would hang until mpirun's SIGKILL a second later).
  void leave_without_finalize() noexcept { finalize_ = false; }

 private:
  bool active_ = false;
  bool finalize_ = true;
  int rank_ = 0;
  int size_ = 1;
  int ranks_on_node_ = 1;
};

}  // namespace rollnoise
