// Hdf5Writer::slices: fields streamed one slice at a time, in chunks of several slices, with and
// without shuffle + deflate. Read back by the independent reader (Hdf5Reader, a separate HDF5
// session in a child process), every value must come back exactly as the float it was written
// as, in C order, for 2-D and 3-D datasets and a last chunk that is only partly filled.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "core/hdf5_reader.hpp"
#include "core/hdf5_writer.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

// A field like the contact force: zero outside a moving patch, smooth inside.
float value(std::size_t n, std::size_t r, std::size_t c) {
  const double x = static_cast<double>(c) - 0.5 * static_cast<double>(n);
  return std::abs(x - 20.0) < 8.0 ? static_cast<float>(1.0 + std::sin(0.3 * x + 0.1 * static_cast<double>(r))) : 0.0f;
}

struct Written {
  fs::path path;
  std::uintmax_t bytes;
};

Written write_field(const std::string& name, std::size_t count, std::size_t rows, std::size_t cols,
                    Hdf5Writer::StreamLayout layout) {
  const fs::path path = fs::path(::testing::TempDir()) / name;
  {
    Hdf5Writer h5(path);
    auto stream = h5.slices("/group/field", count, rows, cols, "N", "test field", layout);
    std::vector<float> slice(std::max<std::size_t>(rows, 1) * cols);
    for (std::size_t n = 0; n < count; ++n) {
      for (std::size_t r = 0; r < std::max<std::size_t>(rows, 1); ++r)
        for (std::size_t c = 0; c < cols; ++c) slice[r * cols + c] = value(n, r, c);
      stream->append(slice.data());
    }
    stream->finish();
    stream.reset();
    h5.close();
  }
  return {path, fs::file_size(path)};
}

void expect_read_back(const fs::path& path, std::size_t count, std::size_t rows, std::size_t cols) {
  const Hdf5Array a = Hdf5Reader(path).read_numbers("/group/field", 3, 1u << 24);
  const std::vector<std::size_t> dims =
      rows > 0 ? std::vector<std::size_t>{count, rows, cols} : std::vector<std::size_t>{count, cols};
  ASSERT_EQ(a.dims, dims);
  std::size_t k = 0;
  for (std::size_t n = 0; n < count; ++n)
    for (std::size_t r = 0; r < std::max<std::size_t>(rows, 1); ++r)
      for (std::size_t c = 0; c < cols; ++c, ++k)
        ASSERT_EQ(a.values[k], static_cast<double>(value(n, r, c))) << n << ' ' << r << ' ' << c;
}

TEST(Hdf5SliceStream, ChunksOfSeveralSlicesReadBackExactlyIn2dAnd3d) {
  // 23 slices in chunks of 5: the last chunk holds 3.
  for (const int deflate : {0, 1}) {
    const Written two = write_field("stream2d_" + std::to_string(deflate) + ".h5", 23, 0, 64, {5, deflate});
    expect_read_back(two.path, 23, 0, 64);
    const Written three = write_field("stream3d_" + std::to_string(deflate) + ".h5", 23, 4, 32, {5, deflate});
    expect_read_back(three.path, 23, 4, 32);
  }
}

TEST(Hdf5SliceStream, ShuffleAndDeflateShrinkAFieldThatIsMostlyZero) {
  const Written plain = write_field("plain.h5", 200, 0, 400, {50, 0});
  const Written packed = write_field("packed.h5", 200, 0, 400, {50, 1});
  expect_read_back(packed.path, 200, 0, 400);
  // 96 % of the values are zero: deflate must take off well over half of the 320 kB.
  EXPECT_GT(plain.bytes, 320000u);
  EXPECT_LT(packed.bytes, plain.bytes / 3);
}

TEST(Hdf5SliceStream, MoreSlicesThanDeclaredIsALogicError) {
  Hdf5Writer h5(fs::path(::testing::TempDir()) / "overflow.h5");
  auto stream = h5.slices("/f", 2, 0, 3, "m", "two slices", {2, 0});
  const float slice[3] = {1, 2, 3};
  stream->append(slice);
  stream->append(slice);
  EXPECT_THROW(stream->append(slice), std::logic_error);
}

}  // namespace
}  // namespace rollnoise
