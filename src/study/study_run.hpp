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
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/cache_folder.hpp"
#include "study/study_cases.hpp"
#include "study/study_file.hpp"

namespace rollnoise {

class MpiSession;
class ProgressSink;

struct StudyRunOptions {
  std::filesystem::path out;  // the study's folder
  int threads = 0;            // cases side by side on this rank; 0: one per core (one under mpirun)
  bool fail_fast = false;     // stop starting cases after the first failure (on any rank)
  bool progress = true;       // cases done, with an ETA, on a terminal (not in CI)
  // The cache folder the cases share (CaseRunOptions::cache); std::nullopt: none.
  std::optional<std::filesystem::path> cache = default_cache_directory();
  // --cache-limit (CaseRunOptions::cache_limit); none: each case's [radiation] cache_limit, else the default.
  std::optional<std::uint64_t> cache_limit;
  // Told of the cases done out of this rank's cases (core/progress.hpp); none: nobody.
  ProgressSink* progress_sink = nullptr;
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

// A whole study as `rollnoise study` runs it (what the command line and the Python module's
// rollnoise.study call): the study file read and every key checked, a study of more than
// kStudyCasesWithoutYes cases refused without `yes`, the folder prepared (`options.out`, empty:
// out/<[study] name>; cases/ removed first with `restart`; the staging folders of cases cut off
// by an earlier run removed), this rank's cases run (run_study_cases), and on rank 0 the
// results written (study_results.hpp). On Ctrl-C every rank stops and Interrupted is thrown
// (under MPI without MPI_Finalize at the end).
// Above this many cases a study asks for --yes (a typo in a list can make thousands).
inline constexpr std::size_t kStudyCasesWithoutYes = 200;

struct StudyRun {
  std::filesystem::path out;
  std::size_t cases = 0;
  nlohmann::json summary;  // what summary.json holds, on rank 0 (null on the others)
};
StudyRun run_study(const std::string& study_file, StudyRunOptions options, bool restart, bool yes, MpiSession& mpi);

}  // namespace rollnoise
