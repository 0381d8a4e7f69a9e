#pragma once
// Files that a case or model file names ([tyre] file, [road] surface, [road] file, a tabulated
// tyre's table): where each is found, and which of them lie outside the folder they were
// looked up in. Such paths are allowed (a case may share a profile with others through
// "../profiles/x.csv" or a symlink), but whoever reads a run's results should see that the
// run read files from elsewhere than its case's folder: the summary lists them.
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace rollnoise {

// A named file and where it was found.
struct ReferencedFile {
  std::filesystem::path path;  // what the reader opens
  // The folder the relative name was taken from: the naming file's folder, the current folder
  // or a folder above the naming file (resolve_referenced_file's search). Empty for an
  // absolute name, which says plainly where it points.
  std::filesystem::path base;
};

// Finds a file named in a case file: relative to the case file's folder, then to the current
// folder, then to each folder above the case file (so "models/tyres/x.toml" works from a case
// anywhere in the project). A name found nowhere gives the path beside the case file (whose
// reader reports it missing).
ReferencedFile find_referenced_file(const std::filesystem::path& referenced, const std::filesystem::path& case_file);

// A relative name that leaves the folder it was looked up in, through ".." or a symlink.
struct PathOutsideCaseFolder {
  std::string key;       // "[road] file"
  std::string file;      // the case or library file that names it
  std::string written;   // the name as written
  std::string resolved;  // the file it reaches, ".." and symlinks resolved
};

// The resolved path when `found` is a relative name whose file lies outside its base folder once
// ".." and symlinks are resolved (both sides canonical); empty when it stays inside, or when the
// file does not exist (its reader reports that).
std::filesystem::path outside_base(const ReferencedFile& found);

// What one case's files named outside their folders, in the order found. Shared by a CaseFile
// and the ConfigTables taken from it, which note what the readers resolve; guarded by a mutex,
// so a stage that builds from the tables on several threads cannot corrupt it.
class PathsOutsideCaseFolder {
 public:
  // Notes `found` (named by `written` under `key` in `file`) when it lies outside its base;
  // a path already noted for the same key and file is not repeated.
  void note(const std::string& key, const std::string& file, const std::string& written, const ReferencedFile& found);
  std::vector<PathOutsideCaseFolder> entries() const;

 private:
  mutable std::mutex mutex_;
  std::vector<PathOutsideCaseFolder> entries_;
};

// [{"key": ..., "file": ..., "path": <as written>, "resolved": ...}, ...] for summary.json.
void to_json(nlohmann::json& out, const PathOutsideCaseFolder& path);

}  // namespace rollnoise
