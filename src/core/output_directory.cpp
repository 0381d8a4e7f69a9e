#include "core/output_directory.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

namespace {

// ".NAME.TAG-PID", a hidden sibling of the destination. (Built by appending: GCC 12 warns
// falsely, -Wrestrict, on a chain of string + string here.)
fs::path sibling(const fs::path& destination, const char* tag) {
  std::string name = ".";
  name += destination.filename().string();
  name += tag;
  name += std::to_string(::getpid());
  return destination.parent_path() / name;
}

bool is_rollnoise_output(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "summary.json", ec) || fs::exists(dir / "report.json", ec);
}

}  // namespace

StagedOutputDirectory::StagedOutputDirectory(fs::path destination)
    : destination_(std::move(destination)) {
  std::error_code ec;
  if (destination_.filename().empty()) destination_ = destination_.parent_path();
  // The destination is renamed into place: it cannot be the folder we stand in, or hold it.
  const fs::path here = fs::current_path(ec);
  const fs::path target = fs::weakly_canonical(fs::absolute(destination_, ec), ec);
  const auto mismatch = std::mismatch(target.begin(), target.end(), here.begin(), here.end());
  if (destination_.empty() || mismatch.first == target.end()) {
    throw InputError("--out", destination_.empty() ? "\"\"" : destination_.string(),
                     "is the current folder or one that holds it; choose a new folder");
  }
  if (fs::exists(destination_, ec)) {
    if (!fs::is_directory(destination_, ec)) {
      throw InputError("--out", destination_.string(), "exists and is not a folder");
    }
    if (!fs::is_empty(destination_, ec) && !is_rollnoise_output(destination_)) {
      throw InputError("--out", destination_.string(),
                       "exists and is not an earlier rollnoise output; choose a new folder");
    }
  }
  const fs::path parent = destination_.has_parent_path() ? destination_.parent_path() : fs::path(".");
  for (fs::path p = parent; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_parents_.push_back(p);
  }
  fs::create_directories(parent, ec);
  if (ec) throw InputError("--out", parent.string(), "cannot create folder: " + ec.message());
  staging_ = sibling(destination_, ".partial-");
  fs::remove_all(staging_, ec);
  fs::create_directory(staging_, ec);
  if (ec) throw InputError("--out", staging_.string(), "cannot create folder: " + ec.message());
}

StagedOutputDirectory::~StagedOutputDirectory() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
    for (const auto& p : created_parents_) fs::remove(p, ec);  // only while empty
  }
}

void StagedOutputDirectory::commit() {
  std::error_code ec;
  fs::path old;
  if (fs::exists(destination_, ec)) {
    old = sibling(destination_, ".old-");
    fs::remove_all(old, ec);
    fs::rename(destination_, old, ec);
    if (ec) throw std::runtime_error("cannot move " + destination_.string() + " aside: " + ec.message());
  }
  fs::rename(staging_, destination_, ec);
  if (ec) {
    if (!old.empty()) fs::rename(old, destination_, ec);
    throw std::runtime_error("cannot move results into " + destination_.string() + ": " + ec.message());
  }
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ec);
}

void throw_output_error(const fs::path& path, int error_number) {
  std::string message = "cannot write ";
  message += path.string();
  if (error_number != 0) {
    message += ": ";
    message += std::strerror(error_number);
  }
  if (error_number == ENOSPC || error_number == EFBIG || error_number == EDQUOT) {
    message += " (the disk, a quota or the file-size limit is full: free some space or choose --out elsewhere)";
  }
  throw OutputError(message);
}

void close_output_file(std::ofstream& out, const fs::path& path) {
  // errno still holds the reason of the write that failed: nothing else ran since the stream
  // was last written to.
  if (!out.is_open() || !out) throw_output_error(path, errno);
  errno = 0;
  out.flush();
  if (!out) throw_output_error(path, errno);
  out.close();
  if (!out) throw_output_error(path, errno);
}

void write_text_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  close_output_file(out, path);
}

}  // namespace rollnoise
