#pragma once
// What the cache folder (core/cache_folder.hpp) holds, for `rollnoise cache list|clear`: the
// entries of every cache of rollnoise, each with its size, age and what it holds.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rollnoise {

struct CacheEntry {
  std::filesystem::path path;
  std::string kind;         // "radiation", "two_layer table", "mode fits", "unfinished write"
  std::uintmax_t bytes = 0;
  double age_s = 0.0;       // since it was last written
  std::string holds;        // one line on its content
};

// The entries of `folder`, by name; files no cache of rollnoise writes are left out (and left
// alone by clear_cache). An absent folder has none.
std::vector<CacheEntry> cache_entries(const std::filesystem::path& folder);

// Removes every entry cache_entries() lists (never other files, nor the folder); returns how
// many files and bytes went. std::runtime_error naming a file that cannot be removed.
struct ClearedCache {
  std::size_t files = 0;
  std::uintmax_t bytes = 0;
};
ClearedCache clear_cache(const std::filesystem::path& folder);

}  // namespace rollnoise
