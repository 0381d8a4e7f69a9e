#include "core/referenced_file.hpp"

#include <algorithm>
#include <system_error>

#include <nlohmann/json.hpp>

namespace rollnoise {
namespace fs = std::filesystem;

ReferencedFile find_referenced_file(const fs::path& referenced, const fs::path& case_file) {
  if (referenced.is_absolute()) return {referenced, {}};
  std::error_code ec;
  const fs::path case_dir = case_file.parent_path();
  const fs::path beside = case_dir / referenced;
  if (fs::exists(beside, ec)) return {beside, case_dir.empty() ? fs::path(".") : case_dir};
  if (fs::exists(referenced, ec)) return {referenced, fs::path(".")};
  for (fs::path dir = fs::absolute(case_dir, ec); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
    if (fs::exists(dir / referenced, ec)) return {dir / referenced, dir};
  }
  return {beside, case_dir.empty() ? fs::path(".") : case_dir};  // does not exist: its reader reports it
}

fs::path outside_base(const ReferencedFile& found) {
  if (found.base.empty()) return {};
  std::error_code ec;
  // Canonical on both sides: ".." is resolved and every symlink followed, in the name and in
  // the base (a case reached through a symlinked folder is inside its own folder).
  const fs::path file = fs::canonical(found.path, ec);
  if (ec) return {};
  const fs::path base = fs::canonical(found.base, ec);
  if (ec) return {};
  // Inside when `base` is a leading run of `file`'s components.
  const auto mismatch = std::mismatch(base.begin(), base.end(), file.begin(), file.end());
  return mismatch.first == base.end() ? fs::path() : file;
}

void PathsOutsideCaseFolder::note(const std::string& key, const std::string& file, const std::string& written,
                                  const ReferencedFile& found) {
  const fs::path outside = outside_base(found);
  if (outside.empty()) return;
  const std::lock_guard lock(mutex_);
  for (const PathOutsideCaseFolder& e : entries_)
    if (e.key == key && e.file == file && e.written == written) return;
  entries_.push_back({key, file, written, outside.string()});
}

std::vector<PathOutsideCaseFolder> PathsOutsideCaseFolder::entries() const {
  const std::lock_guard lock(mutex_);
  return entries_;
}

void to_json(nlohmann::json& out, const PathOutsideCaseFolder& path) {
  out = {{"key", path.key}, {"file", path.file}, {"path", path.written}, {"resolved", path.resolved}};
}

}  // namespace rollnoise
