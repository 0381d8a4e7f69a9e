#pragma once
// `rollnoise simulate CASE.toml [--out DIR] [--set section.key=value]... [--cache DIR | --no-cache]`
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollnoise {

struct SimulateOptions {
  std::string case_file;
  std::string out;  // empty: [output] directory, else out/<case name>
  std::vector<std::string> overrides;
  bool force = false;  // run a case even when it looks too large for the machine
  std::string cache;   // --cache DIR (empty: the default folder, core/cache_folder.hpp)
  bool no_cache = false;
  std::string cache_limit;  // --cache-limit SIZE (empty: the case's, else the default)
};

// Registers the verb on `app`; the options are filled in by the parser.
CLI::App* add_simulate_command(CLI::App& app, SimulateOptions& options);

int run_simulate(const SimulateOptions& options);

}  // namespace rollnoise
