#pragma once
// Running a study's cases: each a normal simulation (run_case) into cases/<id>/ of the study's
// folder, on worker threads, and spread over the MPI ranks (case i on rank i mod size). A case
// whose folder holds its summary.json and the same case.toml is finished and is skipped (the
// folder is committed atomically, so a case cut off leaves none and is redone). To start over,
// the caller removes cases/ first (`--restart`). On Ctrl-C or SIGTERM no case starts, the
// running ones stop and Interrupted is thrown (no outcomes, no results): the finished cases
// stay for a rerun. Under MPI a signal on any rank stops the study on every rank (they agree
// before the gather), and a failure with fail_fast on any rank stops the cases every rank has
// not started yet.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/cache_folder.hpp"
#include "study/study_cases.hpp"
#include "study/study_file.hpp"

namespace rollnoise {

class MpiSession;

struct StudyRunOptions {
  std::filesystem::path out;  // the study's folder
  int threads = 0;            // cases side by side on this rank; 0: one per core (one under mpirun)
  bool fail_fast = false;     // stop starting cases after the first failure (on any rank)
  bool progress = true;       // cases done, with an ETA, on a terminal (not in CI)
  // The cache folder the cases share (CaseRunOptions::cache); std::nullopt: none.
  std::optional<std::filesystem::path> cache = default_cache_directory();
};

struct CaseOutcome {
  std::string status;     // "ok", "failed", or "not run" (after a failure with fail_fast)
  std::string message;    // why it failed
  bool reused = false;    // finished by an earlier run
  double wall_time_s = 0.0;
};

// Runs this rank's share; on rank 0 returns every case's outcome (gathered from the ranks),
// on the others an empty list.
std::vector<CaseOutcome> run_study_cases(const StudySpec& spec, const std::vector<StudyCase>& cases,
                                         const StudyRunOptions& options, const MpiSession& mpi);

std::filesystem::path case_folder(const std::filesystem::path& out, const StudyCase& c);

}  // namespace rollnoise
