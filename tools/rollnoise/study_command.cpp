#include "study_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cache_command.hpp"
#include "core/cache_folder.hpp"
#include "core/cancellation.hpp"
#include "core/error.hpp"
#include "study/mpi_session.hpp"
#include "study/study_cases.hpp"
#include "study/study_file.hpp"
#include "study/study_results.hpp"
#include "study/study_run.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

CLI::App* add_study_command(CLI::App& app, StudyOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "study",
      "Run many cases: the product of a study file's [vary] lists on a base case, each a normal\n"
      "simulation into cases/<id>/, side by side on threads and, under `mpirun -n N`, over the\n"
      "ranks. Writes results.csv, spectra.csv, summary.json and plots. Resumable: finished cases\n"
      "are kept on a rerun. A case that fails is reported and the others go on; the exit status\n"
      "is then 1.");
  cmd->add_option("study", options.study_file, "Study file (TOML) with [study], [set] and [vary]")->required();
  cmd->add_option("--out", options.out, "Output folder (default: out/<study name>); each case is written atomically into cases/<id>/, "
                  "the results when every case has ended");
  cmd->add_option("--threads", options.threads, "Cases side by side on this machine (default: one per core; one per rank under mpirun)")
      ->check(CLI::Range(1, 1024));
  add_cache_options(*cmd, options.cache, options.no_cache, options.cache_limit);
  cmd->add_flag("--fail-fast", options.fail_fast, "Start no more cases after one fails (on any MPI rank)");
  cmd->add_flag("--restart", options.restart, "Run every case again, also those an earlier run finished");
  cmd->add_flag("--yes", options.yes,
                "Run a study of more than " + std::to_string(kStudyCasesWithoutYes) + " cases");
  cmd->footer("Example:\n  rollnoise study models/studies/surfaces_cpx.toml --out out/surfaces\n"
              "  mpirun -n 2 rollnoise study models/studies/surfaces_cpx.toml --out out/surfaces");
  return cmd;
}

int run_study(const StudyOptions& options) {
  MpiSession mpi;
  StudyRunOptions run;
  run.out = options.out;
  run.threads = options.threads;
  run.fail_fast = options.fail_fast;
  // Resolved once for the whole study, so that a folder that cannot be written is one warning.
  run.cache = usable_cache_folder(options.cache, options.no_cache);
  run.cache_limit = parse_cache_limit(options.cache_limit);
  StudyRun study;
  try {
    study = rollnoise::run_study(options.study_file, run, options.restart, options.yes, mpi);
  } catch (const Interrupted& stopped) {
    // Every rank stops together (run_study_cases); rank 0 alone says so, as it alone reports
    // the study, so that Ctrl-C under mpirun gives one line rather than one per rank.
    if (mpi.rank() != 0) return stopped.exit_status();
    throw;
  }
  if (mpi.rank() != 0) return 0;
  const auto& counts = study.summary["cases"];
  std::printf("rollnoise: wrote %s (results.csv, spectra.csv, summary.json, plots): %zu cases, %zu ok (%zu from an earlier run), %zu failed\n",
              study.out.string().c_str(), counts["total"].get<std::size_t>(), counts["ok"].get<std::size_t>(),
              counts["from_earlier_run"].get<std::size_t>(), counts["failed"].get<std::size_t>());
  return counts["ok"].get<std::size_t>() == study.cases ? 0 : 1;
}

}  // namespace rollnoise
