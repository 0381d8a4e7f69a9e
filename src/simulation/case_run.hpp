#pragma once
// One case end to end (ARCHITECTURE.md, src/simulation): validate the case file, run road →
// contact → response → radiation → acoustics → audio, and write the outputs atomically into
// one folder. What `rollnoise simulate` and `rollnoise study` call; it prints nothing but
// warnings, so the callers decide what to say.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/cache_folder.hpp"

namespace rollnoise {

class CaseFile;
class ProgressSink;

struct CaseRunOptions {
  // Progress bars on a terminal (ProgressReporter); a study draws its own instead.
  bool progress = true;
  // Threads for the radiation's anchor solves when the case does not set [radiation] threads
  // (0: every core). A study running cases side by side gives each case fewer.
  int radiation_threads = 0;
  // Written as case.toml beside the outputs, in the same atomic commit (a study's generated
  // case, so that a finished case can be recognised and rerun); empty: none.
  std::string case_text;
  // Run even when the estimate of the run's memory or output exceeds what the machine has
  // (run_size.hpp); otherwise such a case is refused before it starts.
  bool force = false;
  // The cache folder of every cache the run uses (core/cache_folder.hpp: the two-layer tables,
  // the mode fits, the radiation's anchor operators); std::nullopt: none. The command line
  // resolves --cache and --no-cache into this (usable_cache_folder).
  std::optional<std::filesystem::path> cache = default_cache_directory();
  // The cache folder's size limit from --cache-limit, which overrides the case's [radiation]
  // cache_limit (core/cache_limit.hpp); none: the case's, else kDefaultCacheLimitBytes.
  std::optional<std::uint64_t> cache_limit;
  // Told of the run's progress (the contact loop, the radiation's anchors), drawn or not; none:
  // nobody. Must outlive the run.
  ProgressSink* progress_sink = nullptr;
};

struct CaseResult {
  std::filesystem::path out;   // the folder written
  nlohmann::json summary;      // what summary.json holds
  std::string written;         // the files written, for the caller's message
};

// The folder a case writes to without --out: [output] directory, else out/<case file's stem>.
std::filesystem::path default_case_output(const CaseFile& file);

// Runs the case into `out` (replaced atomically; empty: default_case_output). Bad input throws InputError naming the file
// and key; nothing is written then.
CaseResult run_case(const CaseFile& file, const std::filesystem::path& out, const CaseRunOptions& options = {});

}  // namespace rollnoise
