#pragma once
// The first check of a verb's input file: it exists and is a regular file (not a folder or a
// device), else an InputError naming it: "PATH: file not found (or not a regular file)".
#include <filesystem>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace rollnoise {

inline void require_regular_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::path(path), ec))
    throw InputError(path, "", "file not found (or not a regular file)");
}

}  // namespace rollnoise
