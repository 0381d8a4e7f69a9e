// Fuzz target: the stationary laser profilometer format (road/laser_profile.hpp), parsed from
// memory and loaded through the format detection of road/profile_file.hpp.
#include "fuzz_target.hpp"
#include "road/laser_profile.hpp"
#include "road/profile_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollnoise::fuzz::InputFile file(".dat");
  const std::string text = rollnoise::fuzz::as_text(data, size);
  (void)rollnoise::looks_like_laser_profile(text);
  rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_laser_profile(text, "fuzz.dat"); });
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::load_profile_file(file.write(data, size)); });
}
