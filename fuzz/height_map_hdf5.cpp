// Fuzz target: HDF5 height maps (road/height_map_hdf5.hpp, through core/hdf5_reader.hpp), read
// directly and as a road profile (road/profile_file.hpp). libhdf5 itself is not instrumented:
// coverage guides the mutations through rollnoise's checks only.
#include "fuzz_target.hpp"
#include "road/height_map_hdf5.hpp"
#include "road/profile_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollnoise::fuzz::InputFile file(".h5");
  const std::filesystem::path& path = file.write(data, size);
  rollnoise::fuzz::guarded([&] { (void)rollnoise::read_height_map_hdf5(path); });
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::load_profile_file(path); });
}
