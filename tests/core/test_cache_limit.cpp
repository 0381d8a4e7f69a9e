// The cache folder's size limit (core/cache_limit.hpp) and the sizes it is given in
// (core/byte_size.hpp): the least recently used entries go first, a hit counts as a use, files
// that are not entries are neither counted nor removed, and unfinished writes are not counted.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/byte_size.hpp"
#include "core/cache_folder.hpp"
#include "core/cache_limit.hpp"

namespace rollnoise {
namespace {
namespace fs = std::filesystem;

class Folder {
 public:
  Folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("rollnoise_cache_limit_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;
  const fs::path& path() const { return path_; }
  // A file of `bytes` bytes, last used `hours_ago`.
  fs::path file(const std::string& name, std::size_t bytes, int hours_ago) const {
    const fs::path p = path_ / name;
    std::ofstream(p, std::ios::binary) << std::string(bytes, 'x');
    fs::last_write_time(p, fs::file_time_type::clock::now() - std::chrono::hours(hours_ago));
    return p;
  }

 private:
  fs::path path_;
};

TEST(ByteSize, ReadsDecimalAndBinaryUnits) {
  EXPECT_EQ(parse_byte_size("4 GB"), 4'000'000'000u);
  EXPECT_EQ(parse_byte_size("4GB"), 4'000'000'000u);
  EXPECT_EQ(parse_byte_size("500 mb"), 500'000'000u);
  EXPECT_EQ(parse_byte_size("1.5 kB"), 1500u);
  EXPECT_EQ(parse_byte_size("2 GiB"), 2147483648u);
  EXPECT_EQ(parse_byte_size("1 KiB"), 1024u);
  EXPECT_EQ(parse_byte_size("123456"), 123456u);
  EXPECT_EQ(parse_byte_size(" 7 B "), 7u);
  EXPECT_EQ(parse_byte_size("1 TB"), 1'000'000'000'000u);
  for (const char* bad : {"", "GB", "lots", "-3 GB", "0", "0 MB", "4 GBs", "1e9", "inf", "nan GB", "4 G B", "99999999 TB"})
    EXPECT_FALSE(parse_byte_size(bad).has_value()) << bad;
}

TEST(CacheEntryKind, NamesTheCachesFilesAndNothingElse) {
  EXPECT_EQ(cache_entry_kind("radiation-0123abcd.h5"), "radiation");
  EXPECT_EQ(cache_entry_kind("two_layer-0123abcd.h5"), "two_layer table");
  EXPECT_EQ(cache_entry_kind("two_layer-0123abcd-fit-4567.fits"), "mode fits");
  EXPECT_EQ(cache_entry_kind(".radiation-0123abcd.h5.tmp123"), "unfinished write");
  EXPECT_EQ(cache_entry_kind("notes.txt"), "");
  EXPECT_EQ(cache_entry_kind("radiation-0123abcd.csv"), "");
  EXPECT_EQ(cache_entry_kind("my data.h5"), "");
}

// Oldest use first, until the entries fit; other files stay and do not count.
TEST(CacheLimit, RemovesTheLeastRecentlyUsedEntriesUntilTheyFit) {
  const Folder f;
  const fs::path a = f.file("radiation-a.h5", 1000, 5);
  const fs::path b = f.file("radiation-b.h5", 1000, 4);
  const fs::path c = f.file("two_layer-c.h5", 1000, 3);
  const fs::path d = f.file("d.fits", 1000, 2);
  const fs::path e = f.file("radiation-e.h5", 1000, 1);
  const fs::path mine = f.file("notes.txt", 100000, 9);
  const fs::path unfinished = f.file(".radiation-f.h5.tmp42", 100000, 9);

  const CacheTrim nothing = keep_cache_within(f.path(), 5000);
  EXPECT_EQ(nothing.bytes_before, 5000u) << "neither notes.txt nor the unfinished write count";
  EXPECT_EQ(nothing.removed, 0u);

  // b is used now: a, then c go.
  mark_cache_entry_used(b);
  const CacheTrim trim = keep_cache_within(f.path(), 3500);
  EXPECT_EQ(trim.removed, 2u);
  EXPECT_EQ(trim.removed_bytes, 2000u);
  EXPECT_EQ(trim.bytes_after, 3000u);
  EXPECT_FALSE(fs::exists(a));
  EXPECT_FALSE(fs::exists(c));
  for (const fs::path& kept : {b, d, e, mine, unfinished}) EXPECT_TRUE(fs::exists(kept)) << kept;

  // A limit below every entry empties the cache, and only the cache.
  EXPECT_EQ(keep_cache_within(f.path(), 1).bytes_after, 0u);
  for (const fs::path& gone : {b, d, e}) EXPECT_FALSE(fs::exists(gone)) << gone;
  EXPECT_TRUE(fs::exists(mine));
  EXPECT_TRUE(fs::exists(unfinished));
  // An absent folder holds nothing; marking a vanished entry is no error.
  EXPECT_EQ(keep_cache_within(f.path() / "absent", 1).bytes_before, 0u);
  mark_cache_entry_used(a);
  EXPECT_FALSE(fs::exists(a));
}

// A run spares its own entries it has yet to read: the oldest that are not spared go instead, and
// when only spared ones are left the folder stays over the limit.
TEST(CacheLimit, SparedEntriesStayAndTheNextOldestGo) {
  const Folder f;
  const fs::path a = f.file("radiation-a.h5", 1000, 5);
  const fs::path b = f.file("radiation-b.h5", 1000, 4);
  const fs::path c = f.file("radiation-c.h5", 1000, 3);
  const auto spare_a = [&](const fs::path& entry) { return entry.filename() == a.filename(); };
  const CacheTrim trim = keep_cache_within(f.path(), 2000, spare_a);
  EXPECT_EQ(trim.removed, 1u);
  EXPECT_TRUE(fs::exists(a));
  EXPECT_FALSE(fs::exists(b));
  EXPECT_TRUE(fs::exists(c));
  const CacheTrim over = keep_cache_within(f.path(), 500, [](const fs::path&) { return true; });
  EXPECT_EQ(over.removed, 0u);
  EXPECT_EQ(over.bytes_after, 2000u);
  EXPECT_EQ(keep_cache_within(f.path(), 1500).removed, 1u) << "unspared, the oldest goes";
  EXPECT_FALSE(fs::exists(a));
}

}  // namespace
}  // namespace rollnoise
