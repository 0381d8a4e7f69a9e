#pragma once
// The modal receptance table (modal_receptance_table.hpp) in HDF5: layout "rollnoise modal
// receptance v1" (docs/greens/tabulated_layout.md shows it with h5py and MATLAB examples).
//
// Root attributes:
//   layout               string   "rollnoise modal receptance v1" (required, exactly)
//   form                 string   "modal" (required; the only form of v1)
//   radius_m             number   R, m, > 0 (L = 2πR)
//   width_m              number   b, m, > 0
//   lateral_shape        string   "sine" (φ_n = sin(nπy/b)) | "cosine" (φ_n = cos(nπy/b))
//   first_lateral_order  integer  the first n: ≥ 1 for sine, ≥ 0 for cosine
//   source               string   what made the table ("two_layer", a measurement, ...);
//                                 optional on reading, written always
// Datasets at the root (C order; any integer or floating-point type on reading):
//   /frequency      [F]        Hz, finite, ≥ 0, strictly increasing       units = "Hz"
//   /order          [M + 1]    m = 0, 1, …, M
//   /lateral_order  [N]        n = first, first + 1, …, first + N − 1
//   /receptance_re  [N·(M+1)][F]  Re H_zz(m, n, f), m/Pa, finite           units = "m/Pa"
//   /receptance_im  [N·(M+1)][F]  Im H_zz(m, n, f), m/Pa, finite           units = "m/Pa"
// Row (n − first)·(M + 1) + m of the receptance datasets is the mode (m, n); H_mn is the normal
// displacement amplitude of the shape e^{ik_m x}φ_n(y) per normal traction amplitude of the
// same shape (modal_receptance_table.hpp), with the convention α(ω) = ∫ h e^{−iωt} dt (MODEL.md
// §1). The `units` attributes are required on /frequency and the receptance datasets.
//
// Reading: the file is untrusted. Every problem (not HDF5, truncated or garbage bytes, a
// missing or misshaped dataset or attribute, an unknown layout, NaN or infinite values, a
// negative or non-increasing frequency, R or b ≤ 0) is an InputError naming the file, the
// dataset or attribute, what is wrong and what is allowed. The HDF5 library (1.10) can crash or
// hang on a corrupted file, so the file is read in a child process (core/child_process.hpp).
// Sizes are bounded (max_modal_table_values) before anything is allocated.
#include <cstddef>
#include <filesystem>
#include <string_view>

#include "greens/modal_receptance_table.hpp"

namespace rollnoise {

inline constexpr std::string_view modal_table_layout = "rollnoise modal receptance v1";
// At most this many complex values (modes × frequencies): 256 MiB as two datasets of doubles.
// The passenger tyre at M = 508, N = 25 and 121 frequencies has 1.5 million.
inline constexpr std::size_t max_modal_table_values = std::size_t{1} << 24;

// Writes `table` (validated first: InputError) to `path` atomically: into a temporary file in
// the same folder, renamed over `path` only when complete, so that a reader never sees half a
// file. Failures to write are std::runtime_error naming the path.
void write_modal_table(const std::filesystem::path& path, const ModalReceptanceTable& table);

// Reads a table; its `source` is the file's path (for messages).
ModalReceptanceTable read_modal_table(const std::filesystem::path& path);

}  // namespace rollnoise
