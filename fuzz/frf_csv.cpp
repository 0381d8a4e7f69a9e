// Fuzz target: measured FRFs in CSV (calibrate/frf_csv_reader.hpp), with the quantity left to
// the file and given on the command line.
#include "calibrate/frf_csv_reader.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = rollnoise::fuzz::as_text(data, size);
  rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_frf_csv(text, "fuzz.csv", {}); });
  rollnoise::FrfReadOptions given;
  given.quantity = rollnoise::FrfQuantity::accelerance;
  given.quantity_given = true;
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_frf_csv(text, "fuzz.csv", given); });
}
