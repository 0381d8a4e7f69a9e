#include "core/cache_limit.hpp"

#include <fcntl.h>
#include <sys/stat.h>

#include <algorithm>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

#include "core/cache_folder.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

struct Scanned {
  fs::path path;
  std::uint64_t bytes = 0;
  struct timespec used {};
};

// The entry's modification time and size; false when it is gone or not a regular file.
bool stat_entry(const fs::path& path, struct timespec& used, std::uint64_t& bytes) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0 || !S_ISREG(s.st_mode)) return false;
  used = s.st_mtim;
  bytes = static_cast<std::uint64_t>(s.st_size);
  return true;
}

bool same_time(const struct timespec& a, const struct timespec& b) {
  return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

}  // namespace

void mark_cache_entry_used(const fs::path& entry) {
  // Times of now (a null array); a failure (the entry evicted meanwhile, a read-only folder)
  // only leaves the entry looking older.
  (void)::utimensat(AT_FDCWD, entry.c_str(), nullptr, 0);
}

CacheTrim keep_cache_within(const fs::path& folder, std::uint64_t limit, const std::function<bool(const fs::path&)>& spare) {
  CacheTrim trim;
  std::error_code ec;
  std::vector<Scanned> entries;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string kind = cache_entry_kind(it->path());
    if (kind.empty() || kind == "unfinished write") continue;
    Scanned e;
    e.path = it->path();
    if (!stat_entry(e.path, e.used, e.bytes)) continue;
    trim.bytes_before += e.bytes;
    entries.push_back(std::move(e));
  }
  trim.bytes_after = trim.bytes_before;
  if (trim.bytes_before <= limit) return trim;
  // Oldest use first; the name breaks ties, so that runs trimming at once pick the same entries.
  std::sort(entries.begin(), entries.end(), [](const Scanned& a, const Scanned& b) {
    return std::tie(a.used.tv_sec, a.used.tv_nsec, a.path) < std::tie(b.used.tv_sec, b.used.tv_nsec, b.path);
  });
  for (const Scanned& e : entries) {
    if (trim.bytes_after <= limit) break;
    if (spare && spare(e.path)) continue;
    // Used since the scan (a hit, or stored again): keep it. Gone: another run removed it.
    struct timespec now_used {};
    std::uint64_t bytes = 0;
    if (!stat_entry(e.path, now_used, bytes)) {
      trim.bytes_after -= e.bytes;
      continue;
    }
    if (!same_time(now_used, e.used)) continue;
    if (!fs::remove(e.path, ec) || ec) {
      if (!fs::exists(e.path, ec)) trim.bytes_after -= e.bytes;  // removed by another run meanwhile
      continue;
    }
    trim.bytes_after -= e.bytes;
    ++trim.removed;
    trim.removed_bytes += e.bytes;
  }
  return trim;
}

}  // namespace rollnoise
