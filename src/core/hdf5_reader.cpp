#include "core/hdf5_reader.hpp"

#include <hdf5.h>

#include <cstring>
#include <fstream>
#include <limits>
#include <memory>

#include "core/error.hpp"
#include "core/hdf5_handle.hpp"

namespace rollnoise {
namespace {

constexpr std::string_view signature{"\x89HDF\r\n\x1a\n", 8};
constexpr std::size_t max_attribute_bytes = 4096;

using Handle = Hdf5Handle;

// HDF5 prints its error stack to stderr by default; errors here become InputErrors instead.
void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

}  // namespace

bool starts_with_hdf5_signature(std::string_view bytes) { return bytes.substr(0, signature.size()) == signature; }

bool has_hdf5_signature(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  char buffer[8];
  for (std::uintmax_t offset = 0; offset + signature.size() <= size; offset = offset == 0 ? 512 : 2 * offset) {
    in.seekg(static_cast<std::streamoff>(offset));
    if (!in.read(buffer, sizeof buffer)) return false;
    if (starts_with_hdf5_signature(std::string_view(buffer, sizeof buffer))) return true;
  }
  return false;
}

Hdf5Reader::Hdf5Reader(const std::filesystem::path& path) : source_(path.string()) {
  silence_hdf5_errors();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(source_, "", "file not found (or not a regular file)");
  }
  if (!has_hdf5_signature(path)) {
    throw InputError(source_, "", "is not an HDF5 file (no HDF5 signature)");
  }
  file_ = H5Fopen(source_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw InputError(source_, "", "cannot be opened as HDF5 (corrupted or truncated file?)");
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

bool Hdf5Reader::exists(const std::string& path) const {
  if (path.empty() || path == "/") return false;
  return H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0;
}

Hdf5Array Hdf5Reader::read_numbers(const std::string& path, int max_rank, std::size_t max_values) const {
  const auto fail = [&](const std::string& problem) -> InputError { return InputError(source_, path, problem); };
  if (!exists(path)) throw fail("no such dataset");
  H5L_info_t link{};
  if (H5Lget_info(file_, path.c_str(), &link, H5P_DEFAULT) < 0) throw fail("cannot be read (corrupted file?)");
  if (link.type != H5L_TYPE_HARD) throw fail("is a soft or external link; store the dataset itself in the file");
  const Handle dataset(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) throw fail("is not a dataset that can be opened (a group, or a corrupted file?)");

  // Data only from this file: no external raw-data files, no virtual datasets.
  const Handle create(H5Dget_create_plist(dataset.get()), H5Pclose);
  if (!create.valid()) throw fail("cannot be read (corrupted file?)");
  const H5D_layout_t layout = H5Pget_layout(create.get());
  if (layout != H5D_COMPACT && layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED) {
    throw fail("has a storage layout this reader does not accept (virtual dataset?)");
  }
  if (H5Pget_external_count(create.get()) != 0) throw fail("keeps its data in external files; store it in the file");

  const Handle type(H5Dget_type(dataset.get()), H5Tclose);
  if (!type.valid()) throw fail("cannot be read (corrupted file?)");
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_INTEGER && type_class != H5T_FLOAT) throw fail("must hold numbers (integer or floating point)");

  const Handle space(H5Dget_space(dataset.get()), H5Sclose);
  if (!space.valid()) throw fail("cannot be read (corrupted file?)");
  if (H5Sget_simple_extent_type(space.get()) != H5S_SIMPLE) throw fail("must be an array (not a scalar or empty)");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > max_rank || rank > H5S_MAX_RANK) {
    throw fail("has " + std::to_string(rank) + " dimensions; at most " + std::to_string(max_rank) + " allowed here");
  }
  hsize_t dims[H5S_MAX_RANK];
  if (H5Sget_simple_extent_dims(space.get(), dims, nullptr) != rank) throw fail("cannot be read (corrupted file?)");
  Hdf5Array out;
  std::size_t count = 1;
  for (int d = 0; d < rank; ++d) {
    if (dims[d] == 0) throw fail("is empty");
    if (dims[d] > max_values || count > max_values / dims[d]) {
      throw fail("is too large (more than " + std::to_string(max_values) + " values)");
    }
    count *= static_cast<std::size_t>(dims[d]);
    out.dims.push_back(static_cast<std::size_t>(dims[d]));
  }
  out.values.resize(count);
  if (H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data()) < 0) {
    throw fail("its data cannot be read (corrupted file, or numbers that do not convert to double)");
  }
  return out;
}

std::optional<std::string> Hdf5Reader::string_attribute(const std::string& object, const std::string& name) const {
  const std::string where = object + " attribute " + name;
  const auto fail = [&](const std::string& problem) -> InputError { return InputError(source_, where, problem); };
  const htri_t present = H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT);
  if (present < 0) throw fail("cannot be read (corrupted file?)");
  if (present == 0) return std::nullopt;
  const Handle attribute(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) throw fail("cannot be opened (corrupted file?)");
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) throw fail("must be a string");
  const Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (!space.valid()) throw fail("cannot be read (corrupted file?)");
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points != 1) throw fail("must be a single string");
  const htri_t variable = H5Tis_variable_str(type.get());
  if (variable < 0) throw fail("cannot be read (corrupted file?)");
  if (variable > 0) {
    const Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!memory.valid() || H5Tset_size(memory.get(), H5T_VARIABLE) < 0) throw fail("cannot be read");
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0) throw fail("cannot be read (corrupted file?)");
    std::string value;
    const bool too_long = text && std::strlen(text) > max_attribute_bytes;
    if (text && !too_long) value = text;
    if (text) H5free_memory(text);
    if (too_long) throw fail("is longer than " + std::to_string(max_attribute_bytes) + " bytes");
    return value;
  }
  const std::size_t size = H5Tget_size(type.get());
  if (size == 0 || size > max_attribute_bytes) {
    throw fail("must be a string of 1 to " + std::to_string(max_attribute_bytes) + " bytes");
  }
  const Handle memory(H5Tcopy(type.get()), H5Tclose);
  if (!memory.valid()) throw fail("cannot be read");
  std::string buffer(size, '\0');
  if (H5Aread(attribute.get(), memory.get(), buffer.data()) < 0) throw fail("cannot be read (corrupted file?)");
  buffer.resize(std::strlen(buffer.c_str()));  // NUL-terminated or NUL-padded
  while (!buffer.empty() && buffer.back() == ' ') buffer.pop_back();  // space-padded
  return buffer;
}

std::optional<double> Hdf5Reader::number_attribute(const std::string& object, const std::string& name) const {
  const std::string where = object + " attribute " + name;
  const auto fail = [&](const std::string& problem) -> InputError { return InputError(source_, where, problem); };
  const htri_t present = H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT);
  if (present < 0) throw fail("cannot be read (corrupted file?)");
  if (present == 0) return std::nullopt;
  const Handle attribute(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) throw fail("cannot be opened (corrupted file?)");
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (!type.valid()) throw fail("cannot be read (corrupted file?)");
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_INTEGER && type_class != H5T_FLOAT) throw fail("must be a number (integer or floating point)");
  const Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (!space.valid()) throw fail("cannot be read (corrupted file?)");
  if (H5Sget_simple_extent_npoints(space.get()) != 1) throw fail("must be a single number");
  double value = 0.0;
  if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
    throw fail("cannot be read (corrupted file, or a number that does not convert to double)");
  }
  return value;
}

}  // namespace rollnoise
