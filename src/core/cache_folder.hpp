#pragma once
// The cache folder that every cache of rollnoise shares (greens/modal_table_cache: two-layer
// tables; greens/fitted_modes_cache: pole–residue fits; radiation/radiation_cache: the
// equivalent-source operators per anchor frequency), and what their files have in common:
// plain names made from a digest, and atomic writes, so that runs sharing the folder (a study's
// threads, two processes) never read half a file and two writers of one entry both leave a
// whole one.
//
// One folder for all of them, chosen the same way everywhere: `--cache DIR` on the command
// line, else $ROLLNOISE_CACHE, else $XDG_CACHE_HOME/rollnoise (when absolute, as the XDG Base
// Directory specification asks), else $HOME/.cache/rollnoise; `--no-cache` uses none.
#include <filesystem>
#include <optional>
#include <string>

namespace rollnoise {

// $ROLLNOISE_CACHE if set (non-empty), else $XDG_CACHE_HOME/rollnoise (if absolute), else
// $HOME/.cache/rollnoise; std::nullopt when none of these is set (then nothing is cached).
std::optional<std::filesystem::path> default_cache_directory();

// Whether `key` can name a cache file: letters, digits, '-', '_', '.', not starting with '.'
// (temporary files start with '.', so a key never names one).
bool is_cache_key(const std::string& key);

// Empty when `directory` exists or can be created and a file can be created in it; otherwise
// why not (the system's message). Leaves nothing behind.
std::string cache_folder_problem(const std::filesystem::path& directory);

// The folder a run uses: none with `disabled`; else `requested`, or default_cache_directory()
// when that is empty. A folder that cannot be written is dropped with one warning on stderr
// ("rollnoise: warning: ... running without the cache"), so that the run goes on uncached.
std::optional<std::filesystem::path> usable_cache_folder(const std::filesystem::path& requested, bool disabled);

// A file being written in the folder of its target under a name of its own (".NAME.tmpRANDOM":
// two writers of the same target, threads or processes, never share one), then renamed onto the
// target, which is atomic on POSIX file systems: a reader sees the old file or the new one,
// never a mixture, and of two writers the last rename wins with a whole file. Removed by the
// destructor unless renamed.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::filesystem::path& target);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::filesystem::path& path() const noexcept { return path_; }
  // std::runtime_error naming both paths when the rename fails.
  void rename_to(const std::filesystem::path& target);

 private:
  std::filesystem::path path_;
  bool kept_ = false;
};

// Whether a file name in the cache folder is a temporary file of TemporaryFile.
bool is_temporary_cache_file(const std::string& file_name);

// What a file in the cache folder is, by its name as the caches name their entries: "radiation"
// (radiation-KEY.h5, radiation/radiation_cache.hpp), "two_layer table" (two_layer-KEY.h5,
// greens/modal_table_cache.hpp), "mode fits" (KEY.fits, greens/fitted_modes_cache.hpp),
// "contact laws" (contact-laws-KEY.h5, contact/contact_law_cache.hpp),
// "unfinished write" (a TemporaryFile); empty for any other file, which no cache of rollnoise
// reads, counts, evicts or clears (a --cache pointed at a folder of one's own loses nothing else).
std::string cache_entry_kind(const std::filesystem::path& file);

}  // namespace rollnoise
