// Fuzz target: line laser profiles in CSV line pairs (road/line_laser_csv.hpp), parsed from
// memory and loaded through the format detection of road/profile_file.hpp (uniform grid,
// dropouts and spikes).
#include "fuzz_target.hpp"
#include "road/line_laser_csv.hpp"
#include "road/profile_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollnoise::fuzz::InputFile file(".csv");
  const std::string text = rollnoise::fuzz::as_text(data, size);
  (void)rollnoise::looks_like_line_laser_csv(text);
  rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_line_laser_csv(text, "fuzz.csv"); });
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::load_profile_file(file.write(data, size)); });
}
