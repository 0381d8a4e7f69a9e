#pragma once
// Reading numeric datasets and string attributes from HDF5 files written by anyone (h5py,
// MATLAB, this program). The file is untrusted: every failure of the HDF5 library is an
// InputError naming the file and the object, HDF5's own error printing is silenced, and a
// dataset's size is checked against a bound before anything is allocated for it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rollnoise {

// True when `bytes` (the start of a file, or the bytes at a possible superblock offset) begin
// with the 8-byte HDF5 signature "\x89HDF\r\n\x1a\n".
bool starts_with_hdf5_signature(std::string_view bytes);
// True when the file holds the HDF5 signature at offset 0, 512, 1024, 2048, ... (the places a
// superblock may sit, after a user block). False for missing or unreadable files.
bool has_hdf5_signature(const std::filesystem::path& path);

struct Hdf5Array {
  std::vector<std::size_t> dims;  // C order: the last index varies fastest
  std::vector<double> values;     // converted to double from any integer or float type
};

class Hdf5Reader {
 public:
  // Opens `path` read-only. A missing file, or one that is not HDF5, is an InputError.
  explicit Hdf5Reader(const std::filesystem::path& path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  const std::string& source() const noexcept { return source_; }
  // Whether a link named `path` ("/x") exists (false for malformed paths).
  bool exists(const std::string& path) const;
  // A dataset of numbers of rank 1 .. max_rank with at most `max_values` elements in total.
  // Anything else (absent, not a dataset, strings, compound types, too large, unreadable) is
  // an InputError naming the file and `path`. Values are not checked for finiteness.
  Hdf5Array read_numbers(const std::string& path, int max_rank, std::size_t max_values) const;
  // A string attribute (fixed or variable length, at most 4096 bytes) of the object at
  // `object`; std::nullopt when the object has no attribute `name`. Other types are an
  // InputError.
  std::optional<std::string> string_attribute(const std::string& object, const std::string& name) const;
  // A number attribute (one integer or floating-point value, scalar or an array of one),
  // converted to double; std::nullopt when absent. Other types are an InputError. The value is
  // not checked for finiteness.
  std::optional<double> number_attribute(const std::string& object, const std::string& name) const;

 private:
  std::int64_t file_ = -1;
  std::string source_;
};

}  // namespace rollnoise
