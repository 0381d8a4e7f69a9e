#include "cache_command.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "core/byte_size.hpp"
#include "core/cache_folder.hpp"
#include "core/error.hpp"
#include "simulation/cache_contents.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

constexpr char kFolderHelp[] =
    "The cache folder (default: $ROLLNOISE_CACHE, else $XDG_CACHE_HOME/rollnoise, else ~/.cache/rollnoise)";

std::string human_size(std::uintmax_t bytes) {
  char text[32];
  if (bytes >= (std::uintmax_t{1} << 30))
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1 << 30));
  else if (bytes >= (std::uintmax_t{1} << 20))
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
  else if (bytes >= 1024)
    std::snprintf(text, sizeof text, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
  else
    std::snprintf(text, sizeof text, "%ju B", bytes);
  return text;
}

std::string human_age(double seconds) {
  char text[32];
  if (seconds >= 86400.0)
    std::snprintf(text, sizeof text, "%.1f d", seconds / 86400.0);
  else if (seconds >= 3600.0)
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
  else if (seconds >= 60.0)
    std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
  else
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  return text;
}

fs::path folder_of(const CacheOptions& options) {
  if (!options.cache.empty()) return options.cache;
  const std::optional<fs::path> folder = default_cache_directory();
  if (!folder) throw InputError("", "--cache", "no cache folder: none of ROLLNOISE_CACHE, XDG_CACHE_HOME, HOME is set; give --cache DIR");
  return *folder;
}

}  // namespace

void add_cache_options(CLI::App& cmd, std::string& cache, bool& no_cache, std::string& cache_limit) {
  CLI::Option* folder = cmd.add_option(
      "--cache", cache,
      "Cache folder of the radiation's equivalent-source solves and the tyre models' tables and fits (default: "
      "$ROLLNOISE_CACHE, else $XDG_CACHE_HOME/rollnoise, else ~/.cache/rollnoise); one that cannot be written is "
      "skipped with a warning");
  CLI::Option* off =
      cmd.add_flag("--no-cache", no_cache, "Use no cache: solve everything, read and write nothing in the cache folder")
          ->excludes(folder);
  cmd.add_option("--cache-limit", cache_limit,
                 "Size limit of the cache folder, such as 2GB or 500MB: the least recently used entries are removed "
                 "to keep within it (default: the case's [radiation] cache_limit, else 4 GB)")
      ->type_name("SIZE")
      ->excludes(off);
}

std::optional<std::uint64_t> parse_cache_limit(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::optional<std::uint64_t> limit = parse_byte_size(text);
  if (!limit) throw InputError("command line", "--cache-limit", std::string("must be ") + kByteSizeForms + " (got \"" + text + "\")");
  return limit;
}

CLI::App* add_cache_command(CLI::App& app, CacheOptions& options, CLI::App*& list, CLI::App*& clear) {
  CLI::App* cmd = app.add_subcommand(
      "cache",
      "Inspect or empty the cache folder: the radiation's equivalent-source operators per anchor frequency\n"
      "(radiation-*.h5), two_layer modal tables (two_layer-*.h5) and mode fits (*.fits). Files that no cache of\n"
      "rollnoise writes are neither listed nor removed.");
  cmd->require_subcommand(1);
  list = cmd->add_subcommand("list", "List the entries: size, age (since written) and what each holds, then the total");
  list->add_option("--cache", options.cache, kFolderHelp);
  clear = cmd->add_subcommand("clear", "Remove every entry (the folder and files that are not entries stay)");
  clear->add_option("--cache", options.cache, kFolderHelp);
  cmd->footer("Examples:\n  rollnoise cache list\n  rollnoise cache clear --cache /tmp/rollnoise-cache");
  return cmd;
}

int run_cache_list(const CacheOptions& options) {
  const fs::path folder = folder_of(options);
  const std::vector<CacheEntry> entries = cache_entries(folder);
  std::uintmax_t total = 0;
  for (const CacheEntry& e : entries) {
    std::printf("%-40s %10s %8s  %s: %s\n", e.path.filename().string().c_str(), human_size(e.bytes).c_str(),
                human_age(e.age_s).c_str(), e.kind.c_str(), e.holds.c_str());
    total += e.bytes;
  }
  std::printf("rollnoise: %s: %zu entries, %s\n", folder.string().c_str(), entries.size(), human_size(total).c_str());
  return 0;
}

int run_cache_clear(const CacheOptions& options) {
  const fs::path folder = folder_of(options);
  const ClearedCache cleared = clear_cache(folder);
  std::printf("rollnoise: %s: removed %zu entries, %s\n", folder.string().c_str(), cleared.files,
              human_size(cleared.bytes).c_str());
  return 0;
}

}  // namespace rollnoise
