#pragma once
// `rollnoise study STUDY.toml [--out DIR] [--threads N] [--fail-fast] [--restart] [--yes]
//                  [--cache DIR | --no-cache]`
#include <string>

namespace CLI {
class App;
}

namespace rollnoise {

struct StudyOptions {
  std::string study_file;
  std::string out;  // empty: out/<study name>
  int threads = 0;
  bool fail_fast = false;
  bool restart = false;
  bool yes = false;
  std::string cache;  // --cache DIR (empty: the default folder)
  bool no_cache = false;
  std::string cache_limit;  // --cache-limit SIZE (empty: the case's, else the default)
};

CLI::App* add_study_command(CLI::App& app, StudyOptions& options);

int run_study(const StudyOptions& options);

}  // namespace rollnoise
