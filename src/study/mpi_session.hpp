#pragma once
// The ranks a study runs on: under `mpirun` (OpenMPI), every rank of MPI_COMM_WORLD; otherwise
// (or when built without MPI) a single rank. MPI is started only when the program was launched
// by mpirun, so the same binary runs locally without it.
#include <string>
#include <vector>

namespace rollnoise {

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const noexcept { return rank_; }
  int size() const noexcept { return size_; }
  bool active() const noexcept { return active_; }
  // Whether this build can run under MPI at all.
  static bool built_with_mpi() noexcept;

  void barrier() const;
  // Every rank's `text`, on rank 0 (in rank order); empty on the others.
  std::vector<std::string> gather(const std::string& text) const;

 private:
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace rollnoise
