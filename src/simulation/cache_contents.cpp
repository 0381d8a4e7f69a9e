#include "simulation/cache_contents.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <system_error>

#include "core/cache_folder.hpp"
#include "radiation/radiation_cache.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

std::vector<CacheEntry> cache_entries(const fs::path& folder) {
  std::vector<CacheEntry> out;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return out;
  const auto now = fs::file_time_type::clock::now();
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    CacheEntry e;
    e.path = entry.path();
    e.kind = cache_entry_kind(e.path);
    if (e.kind.empty()) continue;
    e.bytes = entry.file_size(ec);
    e.age_s = std::max(0.0, std::chrono::duration<double>(now - entry.last_write_time(ec)).count());
    if (e.kind == "radiation")
      e.holds = describe_radiation_entry(e.path);
    else if (e.kind == "two_layer table")
      e.holds = "modal receptance table of a two_layer tyre (greens/modal_table_cache.hpp)";
    else if (e.kind == "mode fits")
      e.holds = "pole-residue fits of a tyre's modes (greens/fitted_modes_cache.hpp)";
    else if (e.kind == "contact laws")
      e.holds = "the per-cell texture contact laws of a road under a tyre's grid (contact/contact_law_cache.hpp)";
    else
      e.holds = "a write that did not finish (a run stopped while storing); safe to remove";
    out.push_back(std::move(e));
  }
  std::sort(out.begin(), out.end(), [](const CacheEntry& a, const CacheEntry& b) { return a.path < b.path; });
  return out;
}

ClearedCache clear_cache(const fs::path& folder) {
  ClearedCache cleared;
  for (const CacheEntry& e : cache_entries(folder)) {
    std::error_code ec;
    fs::remove(e.path, ec);
    if (ec) throw std::runtime_error("cannot remove " + e.path.string() + ": " + ec.message());
    ++cleared.files;
    cleared.bytes += e.bytes;
  }
  return cleared;
}

}  // namespace rollnoise
