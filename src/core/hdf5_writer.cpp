#include "core/hdf5_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <stdexcept>

#include "core/hdf5_handle.hpp"

namespace rollnoise {
namespace {

// HDF5 closes what is still open when the process exits (an atexit handler). A file whose
// writes failed (a full disk, a file-size limit) cannot be closed, and libhdf5 1.10 crashes
// (SIGSEGV in H5F__close_cb) when its handler tries again at exit, turning a clean "cannot
// write" and exit status 1 into a crash. Every HDF5 object here is closed by RAII, so the
// handler has nothing to do: it is switched off before main() makes any HDF5 call.
[[maybe_unused]] const bool hdf5_exit_handler_off = H5dont_atexit() >= 0;

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

hid_t checked(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5: " + what + " failed");
  return id;
}

using Handle = Hdf5Handle;

Handle link_creation_with_parents() {
  Handle list(checked(H5Pcreate(H5P_LINK_CREATE), "property list"), H5Pclose);
  check(H5Pset_create_intermediate_group(list.get(), 1), "intermediate groups");
  return Handle(H5Pcopy(list.get()), H5Pclose);
}

void write_string_attribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type(checked(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
  check(H5Tset_size(type.get(), value.empty() ? 1 : value.size()), "string size");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "string padding");
  Handle space(checked(H5Screate(H5S_SCALAR), "scalar space"), H5Sclose);
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  Handle attribute(checked(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                           "attribute " + name),
                   H5Aclose);
  check(H5Awrite(attribute.get(), type.get(), value.c_str()), "attribute " + name);
}

void write_double_attribute(hid_t object, const std::string& name, const double* values, hsize_t count) {
  Handle space(checked(count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), "space"),
               H5Sclose);
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  Handle attribute(checked(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                           "attribute " + name),
                   H5Aclose);
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, values), "attribute " + name);
}

void describe(hid_t dataset, const std::string& units, const std::string& description) {
  write_string_attribute(dataset, "units", units);
  write_string_attribute(dataset, "description", description);
}

}  // namespace

Hdf5Writer::Hdf5Writer(const std::filesystem::path& path) {
  // Errors become exceptions with context; HDF5's own stack printing would only add noise.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(path.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("HDF5: cannot create " + path.string());
}

Hdf5Writer::~Hdf5Writer() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5Writer::close() {
  const hid_t file = file_;
  file_ = -1;
  if (file >= 0) check(H5Fclose(file), "closing the file");
}

void Hdf5Writer::group(const std::string& path) {
  if (H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0) return;
  const Handle links = link_creation_with_parents();
  Handle g(checked(H5Gcreate2(file_, path.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT), "group " + path),
           H5Gclose);
}

void Hdf5Writer::write(const std::string& path, const Eigen::VectorXd& data, const std::string& units,
                       const std::string& description) {
  const hsize_t size = static_cast<hsize_t>(data.size());
  Handle space(checked(H5Screate_simple(1, &size, nullptr), "space"), H5Sclose);
  const Handle links = link_creation_with_parents();
  Handle dataset(checked(H5Dcreate2(file_, path.c_str(), H5T_IEEE_F64LE, space.get(), links.get(), H5P_DEFAULT,
                                    H5P_DEFAULT),
                         "dataset " + path),
                 H5Dclose);
  check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write " + path);
  describe(dataset.get(), units, description);
}

void Hdf5Writer::write_integers(const std::string& path, const std::vector<std::int64_t>& data,
                                const std::string& units, const std::string& description) {
  const hsize_t size = static_cast<hsize_t>(data.size());
  Handle space(checked(H5Screate_simple(1, &size, nullptr), "space"), H5Sclose);
  const Handle links = link_creation_with_parents();
  Handle dataset(checked(H5Dcreate2(file_, path.c_str(), H5T_STD_I64LE, space.get(), links.get(), H5P_DEFAULT,
                                    H5P_DEFAULT),
                         "dataset " + path),
                 H5Dclose);
  check(H5Dwrite(dataset.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write " + path);
  describe(dataset.get(), units, description);
}

void Hdf5Writer::write(const std::string& path, const Eigen::MatrixXd& data, const std::string& units,
                       const std::string& description) {
  const hsize_t dims[2] = {static_cast<hsize_t>(data.rows()), static_cast<hsize_t>(data.cols())};
  Handle space(checked(H5Screate_simple(2, dims, nullptr), "space"), H5Sclose);
  const Handle links = link_creation_with_parents();
  Handle dataset(checked(H5Dcreate2(file_, path.c_str(), H5T_IEEE_F64LE, space.get(), links.get(), H5P_DEFAULT,
                                    H5P_DEFAULT),
                         "dataset " + path),
                 H5Dclose);
  // HDF5 stores C order: the row-major copy of the matrix.
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = data;
  check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, row_major.data()), "write " + path);
  describe(dataset.get(), units, description);
}

namespace {

// A dataset [rows][cols] of `file_type` from C-order `values` of `memory_type`, in chunks of
// about 64 kB of whole rows, shuffled and deflated.
void write_deflated(hid_t file, const std::string& path, hid_t file_type, hid_t memory_type, std::size_t value_size,
                    hsize_t rows, hsize_t cols, const void* values, int deflate_level, const std::string& units,
                    const std::string& description) {
  const hsize_t dims[2] = {rows, cols};
  Handle space(checked(H5Screate_simple(2, dims, nullptr), "space"), H5Sclose);
  Handle properties(checked(H5Pcreate(H5P_DATASET_CREATE), "properties"), H5Pclose);
  if (rows > 0 && cols > 0) {
    const hsize_t row_bytes = cols * value_size;
    const hsize_t chunk[2] = {std::clamp<hsize_t>((hsize_t{1} << 16) / row_bytes, 1, rows), cols};
    check(H5Pset_chunk(properties.get(), 2, chunk), "chunking");
    if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0) throw std::runtime_error("HDF5: this libhdf5 has no deflate filter");
    check(H5Pset_shuffle(properties.get()), "shuffle filter");
    check(H5Pset_deflate(properties.get(), static_cast<unsigned>(std::clamp(deflate_level, 1, 9))), "deflate filter");
  }
  const Handle links = link_creation_with_parents();
  Handle dataset(checked(H5Dcreate2(file, path.c_str(), file_type, space.get(), links.get(), properties.get(),
                                    H5P_DEFAULT),
                         "dataset " + path),
                 H5Dclose);
  if (rows > 0 && cols > 0)
    check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), "write " + path);
  describe(dataset.get(), units, description);
}

}  // namespace

void Hdf5Writer::write_compressed(const std::string& path, const Eigen::MatrixXd& data, int deflate_level,
                                  const std::string& units, const std::string& description) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = data;
  write_deflated(file_, path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), static_cast<hsize_t>(data.rows()),
                 static_cast<hsize_t>(data.cols()), row_major.data(), deflate_level, units, description);
}

void Hdf5Writer::write_compressed(const std::string& path,
                                  const Eigen::Matrix<std::int16_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& data,
                                  int deflate_level, const std::string& units, const std::string& description) {
  write_deflated(file_, path, H5T_STD_I16LE, H5T_NATIVE_INT16, sizeof(std::int16_t), static_cast<hsize_t>(data.rows()),
                 static_cast<hsize_t>(data.cols()), data.data(), deflate_level, units, description);
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, double value) {
  Handle target(checked(H5Oopen(file_, object.c_str(), H5P_DEFAULT), "open " + object), H5Oclose);
  write_double_attribute(target.get(), name, &value, 1);
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, const std::string& value) {
  Handle target(checked(H5Oopen(file_, object.c_str(), H5P_DEFAULT), "open " + object), H5Oclose);
  write_string_attribute(target.get(), name, value);
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, const std::vector<double>& values) {
  Handle target(checked(H5Oopen(file_, object.c_str(), H5P_DEFAULT), "open " + object), H5Oclose);
  write_double_attribute(target.get(), name, values.data(), static_cast<hsize_t>(values.size()));
}

void Hdf5Writer::integer_attribute(const std::string& object, const std::string& name, std::int64_t value) {
  Handle target(checked(H5Oopen(file_, object.c_str(), H5P_DEFAULT), "open " + object), H5Oclose);
  Handle space(checked(H5Screate(H5S_SCALAR), "space"), H5Sclose);
  if (H5Aexists(target.get(), name.c_str()) > 0) H5Adelete(target.get(), name.c_str());
  Handle attribute(checked(H5Acreate2(target.get(), name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT,
                                      H5P_DEFAULT),
                           "attribute " + name),
                   H5Aclose);
  check(H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value), "attribute " + name);
}

std::unique_ptr<Hdf5Writer::SliceStream> Hdf5Writer::slices(const std::string& path, std::size_t count,
                                                            std::size_t rows, std::size_t cols,
                                                            const std::string& units,
                                                            const std::string& description, StreamLayout layout) {
  if (count == 0 || cols == 0) throw std::invalid_argument("HDF5 slice stream " + path + ": no values");
  const bool three_d = rows > 0;
  const std::size_t chunk_slices = std::clamp<std::size_t>(layout.chunk_slices, 1, count);
  const hsize_t dims[3] = {count, three_d ? rows : cols, cols};
  const hsize_t chunk[3] = {chunk_slices, three_d ? rows : cols, cols};
  const int rank = three_d ? 3 : 2;
  Handle space(checked(H5Screate_simple(rank, dims, nullptr), "space"), H5Sclose);
  Handle properties(checked(H5Pcreate(H5P_DATASET_CREATE), "properties"), H5Pclose);
  check(H5Pset_chunk(properties.get(), rank, chunk), "chunking");
  if (layout.deflate_level > 0) {
    if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0) throw std::runtime_error("HDF5: this libhdf5 has no deflate filter");
    check(H5Pset_shuffle(properties.get()), "shuffle filter");
    check(H5Pset_deflate(properties.get(), static_cast<unsigned>(std::min(layout.deflate_level, 9))), "deflate filter");
  }
  const Handle links = link_creation_with_parents();
  const hid_t dataset = checked(H5Dcreate2(file_, path.c_str(), H5T_IEEE_F32LE, space.get(), links.get(),
                                           properties.get(), H5P_DEFAULT),
                                "dataset " + path);
  try {
    describe(dataset, units, description);
  } catch (...) {
    H5Dclose(dataset);
    throw;
  }
  return std::unique_ptr<SliceStream>(new SliceStream(dataset, count, three_d ? rows : 1, cols, chunk_slices));
}

Hdf5Writer::SliceStream::SliceStream(std::int64_t dataset, std::size_t count, std::size_t rows, std::size_t cols,
                                     std::size_t chunk_slices)
    : dataset_(dataset), count_(count), rows_(rows), cols_(cols), chunk_slices_(chunk_slices) {
  buffer_.reserve(chunk_slices_ * rows_ * cols_);
}

Hdf5Writer::SliceStream::~SliceStream() { H5Dclose(dataset_); }

void Hdf5Writer::SliceStream::append(const float* slice) {
  if (written_ >= count_) throw std::logic_error("HDF5 slice stream: more slices than declared");
  buffer_.insert(buffer_.end(), slice, slice + rows_ * cols_);
  ++written_;
  if (written_ - flushed_ == chunk_slices_) flush();
}

void Hdf5Writer::SliceStream::finish() {
  if (written_ > flushed_) flush();
}

// One whole chunk (or the last, partial one) in a single write: a filtered chunk is compressed
// once, not read back and recompressed per slice.
void Hdf5Writer::SliceStream::flush() {
  Handle file_space(checked(H5Dget_space(dataset_), "space"), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(file_space.get());
  const hsize_t start[3] = {flushed_, 0, 0};
  const hsize_t size[3] = {written_ - flushed_, rank == 3 ? rows_ : cols_, cols_};
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, size, nullptr), "selection");
  Handle memory(checked(H5Screate_simple(rank, size, nullptr), "memory space"), H5Sclose);
  check(H5Dwrite(dataset_, H5T_NATIVE_FLOAT, memory.get(), file_space.get(), H5P_DEFAULT, buffer_.data()),
        "write slices");
  flushed_ = written_;
  buffer_.clear();
}

}  // namespace rollnoise
