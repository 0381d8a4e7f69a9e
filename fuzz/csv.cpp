// Fuzz target: the numeric CSV reader (core/csv.hpp), both ways of treating empty cells.
#include "core/csv.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = rollnoise::fuzz::as_text(data, size);
  rollnoise::fuzz::guarded([&] { (void)rollnoise::parse_numeric_csv(text, "fuzz.csv"); });
  return rollnoise::fuzz::guarded(
      [&] { (void)rollnoise::parse_numeric_csv(text, "fuzz.csv", rollnoise::EmptyCells::as_nan); });
}
