#pragma once
// A file's bytes mapped read-only into memory, for reading large files once without copying
// them (the radiation cache's entries: a warm run checked about 520 MB of them, 45 MB since their
// power operators are rounded, and reading them into a buffer first cost more than checking them).
#include <cstddef>
#include <filesystem>
#include <string_view>

namespace rollnoise {

class MappedFile {
 public:
  // std::runtime_error saying what failed (without the path: the caller names the file).
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  // The file's bytes as they were when it was mapped (an empty view for an empty file).
  std::string_view bytes() const noexcept { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace rollnoise
