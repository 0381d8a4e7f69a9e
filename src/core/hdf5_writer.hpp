#pragma once
// Writing large fields to HDF5 (ARCHITECTURE.md: "HDF5 for large fields"), readable from
// MATLAB (h5read), Python (h5py) and the HDF5 tools. Datasets carry their units and a
// description as attributes. Arrays are written in C order: an Eigen column-major matrix of
// samples × points is stored as [samples][points] by writing its transpose's memory.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

// How a streamed dataset is stored: `chunk_slices` slices to an HDF5 chunk (the stream keeps
// one chunk in memory and writes it whole), and HDF5's shuffle + deflate at `deflate_level`
// (1–9; 0: none). Shuffle groups the bytes of equal significance, so the zeros outside the
// contact and the slowly varying high bytes compress (measured in docs/performance.md).
struct Hdf5StreamLayout {
  std::size_t chunk_slices = 1;
  int deflate_level = 0;
};

class Hdf5Writer {
 public:
  // Creates (or truncates) the file. Throws std::runtime_error on failure.
  explicit Hdf5Writer(const std::filesystem::path& path);
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // Closes the file, throwing std::runtime_error if HDF5 cannot finish writing it (the
  // destructor closes too, but cannot report that). No other call is allowed afterwards.
  void close();

  // A group ("contact", "surface/fields"); parents are created as needed.
  void group(const std::string& path);
  // 1-D dataset of doubles.
  void write(const std::string& path, const Eigen::VectorXd& data, const std::string& units,
             const std::string& description);
  // 1-D dataset of 64-bit integers (indices, orders).
  void write_integers(const std::string& path, const std::vector<std::int64_t>& data, const std::string& units,
                      const std::string& description);
  // 2-D dataset [rows][cols] of doubles from a matrix (any storage order).
  void write(const std::string& path, const Eigen::MatrixXd& data, const std::string& units,
             const std::string& description);
  // 2-D datasets [rows][cols] stored in chunks of whole rows through HDF5's shuffle and deflate
  // filters at `deflate_level` (1–9): doubles, or 16-bit integers (quantised values). h5py,
  // MATLAB and the HDF5 tools read them as any other dataset. An empty matrix is stored plain.
  void write_compressed(const std::string& path, const Eigen::MatrixXd& data, int deflate_level,
                        const std::string& units, const std::string& description);
  void write_compressed(const std::string& path,
                        const Eigen::Matrix<std::int16_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& data,
                        int deflate_level, const std::string& units, const std::string& description);
  // Attributes on a group or dataset ("/" for the file).
  void attribute(const std::string& object, const std::string& name, double value);
  void attribute(const std::string& object, const std::string& name, const std::string& value);
  void attribute(const std::string& object, const std::string& name, const std::vector<double>& values);
  // A 64-bit integer attribute (named apart from attribute(): an int argument would be ambiguous).
  void integer_attribute(const std::string& object, const std::string& name, std::int64_t value);

  using StreamLayout = Hdf5StreamLayout;

  // A float dataset [count][rows][cols] (or [count][cols] when rows is 0) written one slice at a
  // time, for fields too large to keep in memory.
  class SliceStream {
   public:
    ~SliceStream();
    SliceStream(const SliceStream&) = delete;
    SliceStream& operator=(const SliceStream&) = delete;
    // `slice` holds rows × cols values in C order (row-major).
    void append(const float* slice);
    // Writes the slices still buffered; throws if HDF5 cannot. Call once all slices are in
    // (the destructor discards a partial chunk: it runs only when a run failed anyway).
    void finish();
    std::size_t written() const noexcept { return written_; }

   private:
    friend class Hdf5Writer;
    SliceStream(std::int64_t dataset, std::size_t count, std::size_t rows, std::size_t cols, std::size_t chunk_slices);
    void flush();
    std::int64_t dataset_;
    std::size_t count_, rows_, cols_, chunk_slices_, written_ = 0, flushed_ = 0;
    std::vector<float> buffer_;  // slices written_ − flushed_ of the current chunk
  };
  std::unique_ptr<SliceStream> slices(const std::string& path, std::size_t count, std::size_t rows,
                                      std::size_t cols, const std::string& units, const std::string& description,
                                      StreamLayout layout = {});

 private:
  std::int64_t file_;
};

}  // namespace rollnoise
