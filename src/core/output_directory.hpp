#pragma once
// Atomic output: a run writes into a hidden staging folder beside the destination and
// renames it into place only when everything is written, so a failed run leaves no
// half-written results (and an earlier complete result stays until the new one is whole).
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollnoise {

class StagedOutputDirectory {
 public:
  // Checks that `destination` can be replaced: it must not exist, or be an earlier rollnoise
  // output (it holds summary.json or report.json). Creates the staging folder.
  explicit StagedOutputDirectory(std::filesystem::path destination);
  ~StagedOutputDirectory();
  StagedOutputDirectory(const StagedOutputDirectory&) = delete;
  StagedOutputDirectory& operator=(const StagedOutputDirectory&) = delete;

  // Where to write the files now.
  const std::filesystem::path& staging() const noexcept { return staging_; }
  const std::filesystem::path& destination() const noexcept { return destination_; }
  // Moves the staged folder into place, replacing an earlier output.
  void commit();

 private:
  std::filesystem::path destination_;
  std::filesystem::path staging_;
  // Parent folders this object created, deepest first: removed again if the run fails.
  std::vector<std::filesystem::path> created_parents_;
  bool committed_ = false;
};

// A write into the output that failed: the disk is full, a file-size limit (ulimit -f) is
// reached, an I/O error. Exit status 1 with this one message; the staging folder goes with the
// failed run like after any other failure.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "cannot write PATH: REASON", with a hint when the reason is a full disk or a size limit.
[[noreturn]] void throw_output_error(const std::filesystem::path& path, int error_number);

// Closes `out` (flushing what is buffered) and throws OutputError naming `path` and the
// system's reason (errno of the write that failed) when anything written to it failed.
void close_output_file(std::ofstream& out, const std::filesystem::path& path);

// Writes `text` to `path` (inside a staging folder, so plain writes are fine); throws
// OutputError on failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace rollnoise
