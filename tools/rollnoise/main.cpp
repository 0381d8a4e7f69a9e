// rollnoise: tyre/road noise from first principles. One verb per job (ARCHITECTURE.md).
// Exit status: 0 success, 2 bad input (one message naming the file, the key and what is
// allowed), 1 internal failure, 130/143 stopped by SIGINT/SIGTERM (core/cancellation.hpp: the
// partial output is removed, the destination left as it was).
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "core/cancellation.hpp"
#include "core/error.hpp"
#include "core/output_directory.hpp"
#include "analyse_command.hpp"
#include "cache_command.hpp"
#include "calibrate_command.hpp"
#include "greens_command.hpp"
#include "road_command.hpp"
#include "simulate_command.hpp"
#include "study_command.hpp"

namespace {

// Command-line mistakes read like every other bad input: one line, exit status 2.
std::string command_line_error(const CLI::App*, const CLI::Error& error) {
  return "rollnoise: error: command line: " + std::string(error.what()) + " (try --help)\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rollnoise " ROLLNOISE_VERSION
               ": tyre/road noise from first principles (rolling contact with Green's functions)"};
  app.name("rollnoise");
  app.require_subcommand(1);
  app.set_version_flag("--version", ROLLNOISE_VERSION);
  app.failure_message(command_line_error);

  rollnoise::SimulateOptions simulate;
  CLI::App* simulate_cmd = rollnoise::add_simulate_command(app, simulate);
  rollnoise::AnalyseOptions analyse;
  CLI::App* analyse_cmd = rollnoise::add_analyse_command(app, analyse);
  rollnoise::CalibrateOptions calibrate;
  CLI::App* calibrate_cmd = rollnoise::add_calibrate_command(app, calibrate);
  rollnoise::RoadOptions road;
  CLI::App* road_cmd = rollnoise::add_road_command(app, road);
  rollnoise::GreensOptions greens;
  CLI::App* greens_cmd = rollnoise::add_greens_command(app, greens);
  rollnoise::StudyOptions study;
  CLI::App* study_cmd = rollnoise::add_study_command(app, study);
  rollnoise::CacheOptions cache;
  CLI::App* cache_list = nullptr;
  CLI::App* cache_clear = nullptr;
  rollnoise::add_cache_command(app, cache, cache_list, cache_clear);

  // An unknown verb is named as such (CLI11 would only say that a verb is required).
  const auto is_verb = [&app](const std::string& word) {
    for (const CLI::App* verb : app.get_subcommands([](CLI::App*) { return true; }))
      if (verb->get_name() == word) return true;
    return false;
  };
  if (argc > 1 && argv[1][0] != '-' && !is_verb(argv[1])) {
    std::fprintf(stderr, "rollnoise: error: command line: unknown verb '%s'; verbs are: simulate, analyse, calibrate, road, greens, study, cache (see 'rollnoise --help')\n",
                 argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }
  // From here on Ctrl-C and SIGTERM stop the run through its CancellationToken.
  const rollnoise::SignalCancellation cancellation;
  // A file-size limit (ulimit -f) makes a write fail (EFBIG, an OutputError) instead of
  // killing the process with its staging folder left behind.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    if (simulate_cmd->parsed()) return rollnoise::run_simulate(simulate);
    if (analyse_cmd->parsed()) return rollnoise::run_analyse(analyse);
    if (calibrate_cmd->parsed()) return rollnoise::run_calibrate(calibrate);
    if (road_cmd->parsed()) return rollnoise::run_road(road);
    if (greens_cmd->parsed()) return rollnoise::run_greens(greens);
    if (study_cmd->parsed()) return rollnoise::run_study(study);
    if (cache_list->parsed()) return rollnoise::run_cache_list(cache);
    if (cache_clear->parsed()) return rollnoise::run_cache_clear(cache);
  } catch (const rollnoise::Interrupted& stopped) {
    std::fprintf(stderr, "rollnoise: %s: stopped; the partial output was removed\n", stopped.what());
    return stopped.exit_status();
  } catch (const rollnoise::InputError& error) {
    std::fprintf(stderr, "rollnoise: error: %s\n", error.what());
    return 2;
  } catch (const rollnoise::OutputError& error) {
    std::fprintf(stderr, "rollnoise: error: %s; the partial output was removed\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "rollnoise: internal error: %s\n", error.what());
    return 1;
  }
  return 1;
}
