// rollnoise: tyre/road noise from first principles. One verb per job (ARCHITECTURE.md).
// Exit status: 0 success, 2 bad input (one message naming the file, the key and what is
// allowed), 1 internal failure.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "core/error.hpp"
#include "simulate_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"rollnoise " ROLLNOISE_VERSION
               ": tyre/road noise from first principles (rolling contact with Green's functions)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", ROLLNOISE_VERSION);

  rollnoise::SimulateOptions simulate;
  CLI::App* simulate_cmd = rollnoise::add_simulate_command(app, simulate);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }
  try {
    if (simulate_cmd->parsed()) return rollnoise::run_simulate(simulate);
  } catch (const rollnoise::InputError& error) {
    std::fprintf(stderr, "rollnoise: error: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "rollnoise: internal error: %s\n", error.what());
    return 1;
  }
  return 1;
}
