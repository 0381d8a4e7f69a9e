// Fuzz target: universal files, datasets 58 and 58b (core/uff58.hpp), and the FRFs selected
// from them for calibration (calibrate/frf_uff_reader.hpp).
#include "calibrate/frf_uff_reader.hpp"
#include "core/uff58.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  rollnoise::fuzz::guarded([&] {
    std::vector<int> skipped;
    for (const rollnoise::Uff58Record& record : rollnoise::parse_uff58(bytes, "fuzz.uff", &skipped))
      (void)rollnoise::describe_uff58(record);
  });
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_uff_frfs(bytes, "fuzz.uff", {}); });
}
