// Fuzz target: road profile CSV (road/profile_csv.hpp), parsed and then loaded as a road
// profile (road/profile_file.hpp: format detection, uniform spacing, dropouts and spikes).
#include "fuzz_target.hpp"
#include "road/profile_csv.hpp"
#include "road/profile_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollnoise::fuzz::InputFile file(".csv");
  const std::string text = rollnoise::fuzz::as_text(data, size);
  rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_profile_csv(text, "fuzz.csv"); });
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::load_profile_file(file.write(data, size)); });
}
