#pragma once
// Atomic output: a run writes into a hidden staging folder beside the destination and
// renames it into place only when everything is written, so a failed run leaves no
// half-written results (and an earlier complete result stays until the new one is whole).
#include <filesystem>
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

// Writes `text` to `path` (inside a staging folder, so plain writes are fine); throws on
// failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace rollnoise
