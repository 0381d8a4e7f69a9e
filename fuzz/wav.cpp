// Fuzz target: recordings read through libsndfile (audio/wav_file.hpp: read_wav, and the full
// scale carried in the comment). libsndfile is not instrumented.
#include "audio/wav_file.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rollnoise::fuzz::InputFile file(".wav");
  (void)rollnoise::full_scale_from_comment(std::string_view(reinterpret_cast<const char*>(data), size));
  return rollnoise::fuzz::guarded([&] { (void)rollnoise::read_wav(file.write(data, size)); });
}
