#pragma once
// `rollnoise cache list|clear [--cache DIR]`: what the cache folder holds (entries, sizes, what
// they hold, age), and emptying it. Also the --cache/--no-cache options that simulate and study
// share (core/cache_folder.hpp: one folder for every cache).
#include <string>

namespace CLI {
class App;
}

namespace rollnoise {

struct CacheOptions {
  std::string cache;  // --cache DIR (empty: the default folder)
};

// --cache DIR and --no-cache on `cmd`.
void add_cache_options(CLI::App& cmd, std::string& cache, bool& no_cache);

// Registers `cache` with its verbs `list` and `clear`; returns the `list` and `clear` apps
// through the out parameters so that main can tell which was parsed.
CLI::App* add_cache_command(CLI::App& app, CacheOptions& options, CLI::App*& list, CLI::App*& clear);

int run_cache_list(const CacheOptions& options);
int run_cache_clear(const CacheOptions& options);

}  // namespace rollnoise
