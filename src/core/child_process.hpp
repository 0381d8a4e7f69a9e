#pragma once
// Running a piece of work in a child process (fork), for libraries that may crash on untrusted
// input: the HDF5 library (1.10) dereferences corrupted offsets in a file and can end the whole
// program with a segmentation fault. The child does the work and sends its result back through
// a pipe; a crash, a hang or a result too large is an InputError in the parent.
//
// The work must not rely on other threads (the child has only the calling thread) and should
// touch no state the parent needs afterwards (the child's changes are lost). POSIX only.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace rollnoise {

// Runs `work` in a child process and returns the bytes it returned. An InputError thrown by
// `work` is thrown again here, with the same source, key and problem; any other exception is a
// std::runtime_error. If the child dies (a signal, such as a segmentation fault), returns more
// than `max_bytes` or takes longer than `timeout`, the result is
// InputError(source, "", "cannot be read: " + what + " ...").
std::string run_in_child_process(const std::function<std::string()>& work, const std::string& source,
                                 const std::string& what, std::size_t max_bytes,
                                 std::chrono::milliseconds timeout = std::chrono::seconds(120));

// The time a child may take to read a file: 2 s plus 1 s per MB, ample for reading it (which
// runs at hundreds of MB/s), yet a bound for a corrupted file that sends a library into an
// endless loop.
std::chrono::milliseconds time_to_read(const std::filesystem::path& path);

// A child's result as bytes: counts and arrays of doubles, in native byte order (the same
// program packs and unpacks them).
class ChildResultWriter {
 public:
  void count(std::uint64_t n);
  void doubles(const double* values, std::size_t n);
  std::string& bytes() noexcept { return bytes_; }

 private:
  std::string bytes_;
};

// Unpacks what ChildResultWriter packed, in the same order; `bytes` must outlive it. A short
// result is a std::runtime_error naming `what`.
class ChildResultReader {
 public:
  ChildResultReader(std::string_view bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}
  std::uint64_t count();
  // n values into `out`.
  void doubles(double* out, std::size_t n);

 private:
  void take(void* out, std::size_t n);
  std::string_view bytes_;
  std::string what_;
  std::size_t pos_ = 0;
};

}  // namespace rollnoise
