#include "study/study_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/cancellation.hpp"
#include "core/case_file.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "simulation/case_run.hpp"
#include "study/mpi_session.hpp"
#include "study/study_results.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Finished by an earlier run of the same case: committed (summary.json there) from the same
// case file.
bool finished(const fs::path& folder, const std::string& case_text) {
  std::error_code ec;
  return fs::is_regular_file(folder / "summary.json", ec) && read_all(folder / "case.toml") == case_text;
}

// Cases done out of the total with an ETA, on one line of a terminal.
class StudyProgress {
 public:
  StudyProgress(std::string name, std::size_t total, bool wanted)
      : name_(std::move(name)), total_(total), enabled_(wanted && ProgressReporter::wanted()),
        start_(std::chrono::steady_clock::now()) {}
  void update(std::size_t done, std::size_t run, std::size_t failed) {
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = run > 0 ? elapsed / static_cast<double>(run) * static_cast<double>(total_ - done) : 0.0;
    std::fprintf(stderr, "\rstudy %s: %zu/%zu cases, %zu failed, %.0f s elapsed, about %.0f s left   ", name_.c_str(), done,
                 total_, failed, elapsed, left);
    std::fflush(stderr);
  }
  ~StudyProgress() {
    if (enabled_) std::fprintf(stderr, "\n");
  }

 private:
  std::string name_;
  std::size_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

// --fail-fast over the ranks: the first failure on any rank leaves a marker file in the study's
// cases/ folder (which the ranks share already), and every rank looks for it before it starts a
// case, so a failure on one rank stops the cases not yet started on all of them; cases running
// elsewhere finish. A file rather than an MPI message: the failures happen in the case threads
// while only the main thread may call MPI (MPI_THREAD_FUNNELED), and a file leaves no message to
// match or drain before the gather. Hidden, so a study cut off leaves it where the next run's
// start removes it with the other hidden leftovers of cases/.
class FailFastFlag {
 public:
  FailFastFlag(fs::path marker, bool shared) : marker_(std::move(marker)), shared_(shared) {}

  void raise() {
    raised_ = true;
    if (!shared_) return;
    std::ofstream out(marker_);
    out << "a case failed with --fail-fast\n";
    out.close();
    if (!out)
      std::fprintf(stderr, "rollnoise: warning: cannot write %s: the other ranks go on with their cases\n",
                   marker_.string().c_str());
  }
  bool raised() const {
    if (raised_) return true;
    std::error_code ec;
    return shared_ && fs::exists(marker_, ec);
  }
  // Once no rank looks any more (after every rank's cases).
  void clear() const {
    std::error_code ec;
    fs::remove(marker_, ec);
  }

 private:
  fs::path marker_;
  bool shared_;
  std::atomic<bool> raised_{false};
};

}  // namespace

fs::path case_folder(const fs::path& out, const StudyCase& c) { return out / "cases" / c.id; }

std::vector<CaseOutcome> run_study_cases(const StudySpec& spec, const std::vector<StudyCase>& cases,
                                         const StudyRunOptions& options, const MpiSession& mpi) {
  // This rank's cases: i mod size, so every rank gets a mix of the product.
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(mpi.size())) == mpi.rank()) mine.push_back(i);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t workers = std::max<std::size_t>(
      1, std::min(mine.size(), static_cast<std::size_t>(options.threads > 0 ? options.threads
                                                          : mpi.size() > 1 ? 1
                                                                           : static_cast<int>(cores))));
  // The cores shared among the cases running side by side, on every rank of this machine: each
  // case's radiation takes its part (under mpirun -n 2 on 2 cores, one thread each, not two).
  const unsigned rank_cores = std::max(1u, cores / static_cast<unsigned>(std::max(1, mpi.ranks_on_node())));
  const int radiation_threads = std::max(1, static_cast<int>(rank_cores / workers));

  std::vector<CaseOutcome> outcomes(cases.size());
  std::atomic<std::size_t> next{0};
  FailFastFlag stop(options.out / "cases" / ".fail-fast", mpi.size() > 1);
  std::mutex mutex;
  // Ctrl-C or SIGTERM (core/cancellation.hpp): no case starts after it, the running ones stop
  // at their next poll (their staging folders go), the finished ones stay for a rerun, and
  // the Interrupted is rethrown once every worker is back, so that main() exits 130/143
  // rather than counting the stopped cases as failed ones.
  const CancellationToken cancel;
  int interrupted_by = 0;  // the signal that stopped this rank's cases
  std::size_t done = 0, run = 0, failed = 0;
  StudyProgress progress(spec.name, mine.size(), options.progress && mpi.size() == 1);
  const auto work = [&] {
    for (std::size_t i = next++; i < mine.size(); i = next++) {
      const StudyCase& c = cases[mine[i]];
      CaseOutcome& outcome = outcomes[c.index];
      if (options.fail_fast && stop.raised()) {
        outcome.status = "not run";
        outcome.message = "an earlier case failed (--fail-fast)";
        continue;
      }
      const auto started = std::chrono::steady_clock::now();
      try {
        cancel.throw_if_cancelled();
        const toml::table table = study_case_table(spec, c);
        CaseRunOptions run_options;
        run_options.progress = false;
        run_options.radiation_threads = radiation_threads;
        run_options.cache = options.cache;
        run_options.cache_limit = options.cache_limit;
        run_options.case_text = study_case_text(table);
        const fs::path folder = case_folder(options.out, c);
        if (finished(folder, run_options.case_text)) {
          outcome.status = "ok";
          outcome.reused = true;
        } else {
          run_case(study_case_file(spec, table), folder, run_options);
          outcome.status = "ok";
        }
      } catch (const Interrupted& stopped) {
        const std::lock_guard lock(mutex);
        if (!interrupted_by) interrupted_by = stopped.signal_number();
        next = mine.size();
        return;
      } catch (const InputError& error) {
        outcome.status = "failed";
        outcome.message = error.what();
      } catch (const std::exception& error) {
        outcome.status = "failed";
        outcome.message = std::string("internal error: ") + error.what();
      }
      outcome.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const std::lock_guard lock(mutex);
      ++done;
      if (!outcome.reused) ++run;
      if (outcome.status == "failed") {
        ++failed;
        if (options.fail_fast) stop.raise();
        std::fprintf(stderr, "%srollnoise: case %s failed: %s\n", ProgressReporter::wanted() ? "\r" : "", c.id.c_str(),
                     outcome.message.c_str());
      }
      progress.update(done, run, failed);
      if (options.progress_sink) options.progress_sink->report("study " + spec.name, done, mine.size());
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
  }
  // A signal after the last case: the results are not written either (the finished cases are).
  if (!interrupted_by) interrupted_by = cancel.signal_number();
  // Every rank gets here, stopped or not, before the gather: a rank that threw at once would
  // leave the others waiting in the gather (and then in MPI_Finalize) until the watchdog ended
  // them. If any rank was stopped, the whole study is (under mpirun every rank gets the
  // signal, but not at the same point of its work).
  const int study_stopped_by = mpi.max_over_ranks(interrupted_by);
  if (study_stopped_by) {
    if (mpi.rank() == 0) stop.clear();
    throw Interrupted(study_stopped_by);
  }

  // Rank 0 gathers the outcomes of the others' cases.
  nlohmann::json mine_json = nlohmann::json::object();
  for (std::size_t i : mine)
    mine_json[std::to_string(i)] = {{"status", outcomes[i].status},
                                    {"message", outcomes[i].message},
                                    {"reused", outcomes[i].reused},
                                    {"wall_time_s", outcomes[i].wall_time_s}};
  const std::vector<std::string> gathered = mpi.gather(mine_json.dump());
  if (mpi.rank() == 0) stop.clear();  // every rank is past its cases: none looks for it any more
  if (mpi.rank() != 0) return {};
  for (const std::string& text : gathered) {
    const nlohmann::json rank_outcomes = nlohmann::json::parse(text);  // kept: items() refers to it
    for (const auto& [key, value] : rank_outcomes.items()) {
      CaseOutcome& o = outcomes.at(std::stoul(key));
      o.status = value["status"].get<std::string>();
      o.message = value["message"].get<std::string>();
      o.reused = value["reused"].get<bool>();
      o.wall_time_s = value["wall_time_s"].get<double>();
    }
  }
  return outcomes;
}

StudyRun run_study(const std::string& study_file, StudyRunOptions options, bool restart, bool yes, MpiSession& mpi) {
  const auto started = std::chrono::steady_clock::now();
  // Every rank reads the study and the same list of cases.
  const StudySpec spec = read_study_file(study_file);
  if (spec.case_count() > kStudyCasesWithoutYes && !yes)
    throw InputError(study_file, "vary",
                     "makes " + (spec.case_count() == SIZE_MAX ? std::string("too many") : std::to_string(spec.case_count())) +
                         " cases (more than " + std::to_string(kStudyCasesWithoutYes) +
                         "): shorten the lists, or run with --yes");
  const std::vector<StudyCase> cases = study_cases(spec);
  if (options.out.empty()) options.out = fs::path("out") / spec.name;
  const fs::path& out = options.out;
  if (mpi.rank() == 0) {
    if (restart) fs::remove_all(out / "cases");
    fs::create_directories(out / "cases");
    // Staging folders of cases cut off by an earlier run (core/output_directory.hpp).
    for (const auto& entry : fs::directory_iterator(out / "cases"))
      if (entry.path().filename().string().starts_with(".")) fs::remove_all(entry.path());
  }
  mpi.barrier();
  StudyRun result;
  result.out = out;
  result.cases = cases.size();
  std::vector<CaseOutcome> outcomes;
  try {
    outcomes = run_study_cases(spec, cases, options, mpi);
  } catch (const Interrupted&) {
    if (mpi.active()) mpi.leave_without_finalize();
    throw;
  }
  if (mpi.rank() != 0) return result;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  try {
    result.summary = write_study_results(out, spec, cases, outcomes, {{"ranks", mpi.size()}, {"wall_time_s", wall}}, true);
  } catch (const Interrupted&) {
    if (mpi.active()) mpi.leave_without_finalize();  // stopped while it plots: as above
    throw;
  }
  return result;
}

}  // namespace rollnoise
