#pragma once
// The cache folder's size limit (core/cache_folder.hpp), kept by removing the least recently
// used entries. Without it the folder grew by about 500 MB per radiating body until the disk
// was full (issue 30).
//
// Recency is an entry's modification time: a store writes it (the rename keeps the temporary
// file's), and a hit sets it to now (mark_cache_entry_used). The limit counts the entries of
// every cache (cache_entry_kind: radiation operators, two-layer tables, mode fits, contact laws), not the
// unfinished writes, nor files that no cache writes.
//
// Safe while other runs read and write the folder: removing an entry is one unlink, atomic on
// POSIX file systems; a reader that has the file open or mapped keeps its bytes, and a reader
// that comes after finds no entry and solves it again (a miss, not damage). Two runs trimming
// at once each remove the oldest entries they see, so together they may remove a few more than
// needed, never fewer; an entry used since the scan (its time moved) is kept. While runs store
// concurrently the folder may exceed the limit by the entries stored since the last trim, at
// most one per storing thread; each store trims after its rename, so the folder is within the
// limit whenever no store is under way.
#include <cstdint>
#include <filesystem>
#include <functional>

namespace rollnoise {

// The limit when neither --cache-limit nor [radiation] cache_limit gives one: 4 GB, about
// 80 radiating bodies at 50 MB each.
inline constexpr std::uint64_t kDefaultCacheLimitBytes = 4'000'000'000ull;

// Marks an entry as used now (its modification time). A vanished entry is no error.
void mark_cache_entry_used(const std::filesystem::path& entry);

struct CacheTrim {
  std::uint64_t bytes_before = 0;  // the entries' total as scanned
  std::uint64_t bytes_after = 0;   // that total less what was removed
  std::size_t removed = 0;         // entries removed
  std::uint64_t removed_bytes = 0;
};

// Removes the least recently used entries of `folder` until their total is at most `limit`
// bytes. Files that cannot be removed are skipped (another run removed them, or the folder is
// read-only: then nothing can be stored either), and so are those `spare` names (a run's own
// entries it has yet to read: the folder then stays over the limit until it trims again). An
// absent folder holds nothing.
CacheTrim keep_cache_within(const std::filesystem::path& folder, std::uint64_t limit,
                            const std::function<bool(const std::filesystem::path&)>& spare = {});

}  // namespace rollnoise
