#pragma once
// Universal File Format dataset 58 ("function at nodal DOF") and its binary variant 58b:
// time records, FRFs, spectra, PSDs... as written by LMS Test.Lab, Simcenter, catman, pyuff
// and others.
//
// The reader is general: it keeps every header field of the 11 header records and the data in
// double precision (real or complex ordinate, even or uneven abscissa), and leaves the choice
// of what a caller accepts to the caller (`analyse` wants function type 1, time response;
// `calibrate` wants function type 4, FRF): use describe_uff58() and the *_name() helpers for
// a clear message when a record is of the wrong kind.
//
// What is accepted:
// - datasets delimited by lines holding "-1" (format I6), any number of them, in any order;
//   datasets other than 58/58b are skipped (their numbers are reported);
// - LF or CRLF line ends, a UTF-8 byte order mark, blank lines between datasets, a missing
//   newline at the end, a missing closing "-1" at the very end once the data is complete, a
//   stray extra "-1";
// - record 6 in its fixed columns (entity names may contain blanks) or, failing that, as ten
//   blank-separated fields;
// - ASCII data in any of the formats of the specification (6E13.5, 4E20.12, 2(E13.5,E20.12),
//   E13.5,2E20.12) and anything else that separates numbers by blanks, including short last
//   lines, 3-digit exponents, Fortran 'D' exponents, and values that touch ("1.0E-01-2.0E-01");
// - 58b binary blocks, little or big endian, IEEE 754, single or double precision (for uneven
//   double-precision data the abscissa may be single or double precision: the byte count of
//   the block tells which);
// - non-ASCII bytes in text fields: the text is returned as valid UTF-8 (bytes that are not
//   valid UTF-8 are read as Latin-1, so "m/s\xB2" becomes "m/s²").
// Everything else (bad numbers, wrong counts, truncated files, non-finite values,
// unsupported floating-point formats) is an InputError naming the file, the dataset (its
// position in the file and its first line) and what is wrong. The parser survives arbitrary
// bytes and never allocates more than the input can fill.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rollnoise {

// Record 6, field 1 (the codes used by callers; any other non-negative code is kept as is).
namespace uff_function {
inline constexpr int general = 0;
inline constexpr int time_response = 1;
inline constexpr int auto_spectrum = 2;
inline constexpr int cross_spectrum = 3;
inline constexpr int frequency_response = 4;
inline constexpr int transmissibility = 5;
inline constexpr int coherence = 6;
inline constexpr int power_spectral_density = 9;
inline constexpr int spectrum = 12;
}  // namespace uff_function

// Record 7, field 1.
enum class UffOrdinateType : int {
  real_single = 2,
  real_double = 4,
  complex_single = 5,
  complex_double = 6,
};

// Records 8 to 11: the characteristics of one axis.
struct UffAxis {
  int specific_data_type = 0;  // 17 time, 18 frequency, 12 acceleration, 13 excitation force,
                               // 15 pressure, 21 sound pressure ... (uff_specific_data_type_name)
  int length_exponent = 0;
  int force_exponent = 0;
  int temperature_exponent = 0;
  std::string label;  // axis label, "NONE" if unused (as written in the file, trimmed)
  std::string units;  // axis units label, "NONE" if unused
};

struct Uff58Record {
  // Where the record is: its 1-based position among all datasets of the file, and the line
  // of the "-1" that opens it.
  std::size_t position = 0;
  std::size_t line = 0;
  bool binary = false;  // 58b

  std::array<std::string, 5> id_lines;  // records 1-5 (description, ..., date, ...)

  // Record 6: DOF identification.
  int function_type = 0;  // see uff_function
  std::int64_t function_id = 0;
  std::int64_t version_number = 0;
  std::int64_t load_case = 0;
  std::string response_entity;
  std::int64_t response_node = 0;
  int response_direction = 0;  // 0 scalar, ±1..±3 translations X,Y,Z, ±4..±6 rotations
  std::string reference_entity;
  std::int64_t reference_node = 0;
  int reference_direction = 0;

  // Record 7: data form.
  UffOrdinateType ordinate_type = UffOrdinateType::real_single;
  std::size_t points = 0;
  bool even_spacing = true;
  double abscissa_min = 0.0;        // as written (0 for uneven spacing)
  double abscissa_increment = 0.0;  // as written (0 for uneven spacing)
  double z_axis_value = 0.0;

  // Records 8-11.
  UffAxis abscissa_axis;
  UffAxis numerator_axis;    // ordinate (or ordinate numerator)
  UffAxis denominator_axis;  // ordinate denominator (FRFs), specific data type 0 if unused
  UffAxis z_axis;

  // The data, `points` long. The abscissa is always filled (min + k·increment when even).
  // Exactly one of `ordinate` (real data) and `complex_ordinate` (complex data) is filled.
  Eigen::VectorXd abscissa;
  Eigen::VectorXd ordinate;
  Eigen::VectorXcd complex_ordinate;

  bool is_complex() const {
    return ordinate_type == UffOrdinateType::complex_single ||
           ordinate_type == UffOrdinateType::complex_double;
  }
  bool is_time_record() const { return function_type == uff_function::time_response; }
  bool is_frf() const { return function_type == uff_function::frequency_response; }
};

// Every dataset-58/58b record of the file, in file order. When `skipped_datasets` is given, it
// receives the numbers of the other datasets (such as 151, 164, 2411), in file order, so a
// caller can say "the file has no dataset 58" or "dataset 151 mixed in". A file with no
// dataset at all (not a UFF file) is an InputError; a file with only other datasets returns
// an empty vector.
std::vector<Uff58Record> read_uff58(const std::filesystem::path& path,
                                    std::vector<int>* skipped_datasets = nullptr);

// The same for bytes in memory; `source` names them in messages.
std::vector<Uff58Record> parse_uff58(std::string_view bytes, const std::string& source,
                                     std::vector<int>* skipped_datasets = nullptr);

// "time response", "frequency response function", "power spectral density (PSD)", ...;
// "function type N" for codes outside the specification.
std::string uff_function_type_name(int function_type);
// "time", "frequency", "sound pressure", ...; "specific data type N" for unknown codes.
std::string uff_specific_data_type_name(int specific_data_type);
// "real single precision", ... .
std::string uff_ordinate_type_name(UffOrdinateType type);
// One line for messages, such as "dataset 1 (58b, line 1): time response (function type 1),
// 79292 points, real single precision, even abscissa 0 + k*1.52588e-05 s, ordinate Pa,
// 'Mic 01.0Scalar'".
std::string describe_uff58(const Uff58Record& record);

}  // namespace rollnoise
