#pragma once
// Height maps in HDF5: a regular grid r(x_i, y_j) as three datasets at the file's root:
//
//   /x   1-D, nx values, strictly increasing            attribute units = "m" | "mm" | "um"
//   /y   1-D, ny values, strictly increasing            attribute units = "m" | "mm" | "um"
//   /z   2-D, [nx][ny] (C order: z[i][j] at (x_i, y_j))  attribute units = "m" | "mm" | "um"
//
// Any integer or floating-point type; values are converted to metres. x and y must be finite;
// z finite, or NaN where the instrument gave no reading (a dropout). The `units` attribute is
// required on each dataset (a string, fixed or variable length). Sizes are bounded: at most
// max_height_map_values values in /z. Every problem (not HDF5, corrupted, missing dataset or
// attribute, wrong shape) is an InputError naming the file and the dataset. The HDF5 library
// (1.10) can crash on a corrupted file, so the file is read in a child process
// (core/child_process.hpp): a crash there is an InputError here.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rollnoise {

inline constexpr std::size_t max_height_map_values = std::size_t{1} << 25;  // 256 MiB of doubles

struct HeightMapGrid {
  std::vector<double> x;  // m, nx >= 2 values, strictly increasing
  std::vector<double> y;  // m, ny >= 1 values, strictly increasing
  std::vector<double> z;  // m, z[i * ny + j] at (x[i], y[j]); NaN marks a dropout
  std::string source;
  std::size_t dropouts = 0;  // NaN values in z
};

HeightMapGrid read_height_map_hdf5(const std::filesystem::path& path);

}  // namespace rollnoise
