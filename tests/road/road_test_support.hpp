#pragma once
// What the road tests share: a check that a message mentions a part, and a temporary folder that
// test files are written into and that is removed with it.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

#ifndef EXPECT_MENTIONS
#define EXPECT_MENTIONS(message, part) \
  EXPECT_NE(std::string(message).find(part), std::string::npos) << "message: " << (message)
#endif

namespace rollnoise::test {

// A fresh folder under the system's temp folder (named `prefix` and a random number), removed
// with everything in it when the object goes.
class TempFolder {
 public:
  explicit TempFolder(const std::string& prefix) {
    std::random_device device;
    path_ = std::filesystem::temp_directory_path() / (prefix + std::to_string(device()) + std::to_string(device()));
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const noexcept { return path_; }
  // Writes `text` to `relative` inside the folder (creating its folders) and returns its path.
  std::filesystem::path write(const std::string& relative, const std::string& text) const {
    const std::filesystem::path file = path_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace rollnoise::test
