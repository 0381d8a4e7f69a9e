// Fuzz target: tabulated modal receptance tables in HDF5 (greens/modal_table_hdf5.hpp), the
// files behind `model = "tabulated"` and the two-layer tyre's cache.
#include "fuzz_target.hpp"
#include "greens/modal_table_hdf5.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollnoise::fuzz::InputFile file(".h5");
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::read_modal_table(file.write(data, size)); });
}
