// Fuzz target: model files (CaseFile::load_model: the keys of [tyre] at the top level, such as
// models/tyres/*.toml) with --set overrides, then the tyre's parameter readers.
#include "case_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollnoise;
  static const fuzz::InputFile file(".toml");
  std::string text = fuzz::as_text(data, size);
  const std::vector<std::string> overrides = fuzz::split_overrides(text);
  const std::filesystem::path& path =
      file.write(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  return fuzz::guarded([&] { fuzz::check_tyre(CaseFile::load_model(path, overrides).top()); });
}
