#pragma once
// `rollnoise cache list|clear [--cache DIR]`: what the cache folder holds (entries, sizes, what
// they hold, age), and emptying it. Also the --cache/--no-cache/--cache-limit options that
// simulate, study and greens share (core/cache_folder.hpp: one folder for every cache;
// core/cache_limit.hpp: its size limit).
#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace rollnoise {

struct CacheOptions {
  std::string cache;  // --cache DIR (empty: the default folder)
};

// --cache DIR, --no-cache and --cache-limit SIZE on `cmd`.
void add_cache_options(CLI::App& cmd, std::string& cache, bool& no_cache, std::string& cache_limit);

// The bytes of --cache-limit's value; none when it was not given; an InputError naming the
// option when it is not a size.
std::optional<std::uint64_t> parse_cache_limit(const std::string& text);

// Registers `cache` with its verbs `list` and `clear`; returns the `list` and `clear` apps
// through the out parameters so that main can tell which was parsed.
CLI::App* add_cache_command(CLI::App& app, CacheOptions& options, CLI::App*& list, CLI::App*& clear);

int run_cache_list(const CacheOptions& options);
int run_cache_clear(const CacheOptions& options);

}  // namespace rollnoise
