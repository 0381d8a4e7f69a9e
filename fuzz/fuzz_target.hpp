#pragma once
// What every fuzz entry point (fuzz/<target>.cpp) shares. A target's LLVMFuzzerTestOneInput
// hands the bytes to one reader; the reader must return or throw rollnoise::InputError (exit
// status 2 in the program). Anything else (another exception, a sanitizer report, a crash)
// aborts, which libFuzzer records as a crash and the replay driver (fuzz/replay_main.cpp) as a
// failing ctest.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>

#include "core/error.hpp"

namespace rollnoise::fuzz {

// Runs `read`; an InputError is the expected answer to a bad input, anything else aborts.
template <class Read>
int guarded(Read&& read) {
  try {
    read();
  } catch (const InputError& error) {
    if (std::string_view(error.what()).empty()) {
      std::fprintf(stderr, "fuzz: an InputError with an empty message\n");
      std::abort();
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fuzz: %s escaped the reader: %s\n", typeid(error).name(), error.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: a non-standard exception escaped the reader\n");
    std::abort();
  }
  return 0;
}

// A file holding the input, for readers that take a path (libsndfile, HDF5, the case file with
// its relative references). One per process and suffix, in the temp folder; removed at exit.
class InputFile {
 public:
  explicit InputFile(const std::string& suffix)
      : path_(std::filesystem::temp_directory_path() /
              ("rollnoise_fuzz_" + std::to_string(::getpid()) + suffix)) {}
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::fprintf(stderr, "fuzz: cannot write %s\n", path_.c_str());
      std::abort();
    }
    return path_;
  }

 private:
  std::filesystem::path path_;
};

inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace rollnoise::fuzz
