// Fuzz target: case files (core/case_file.hpp) with --set overrides, then the readers of
// their sections: [tyre] (parameters; the cheap point models are built), [rolling] (both
// settings readers), [road] (a 1 m profile: random, sine, cleat and file roads), [output].
#include "case_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollnoise;
  static const fuzz::InputFile file(".toml");
  std::string text = fuzz::as_text(data, size);
  const std::vector<std::string> overrides = fuzz::split_overrides(text);
  const std::filesystem::path& path =
      file.write(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  return fuzz::guarded([&] {
    const CaseFile cases = CaseFile::load(path, overrides);
    fuzz::guarded([&] { cases.reject_unknown_sections({"tyre", "road", "rolling", "radiation", "output"}); });
    if (cases.has_section("tyre")) fuzz::check_tyre(cases.section("tyre"));
    if (cases.has_section("rolling")) {
      fuzz::guarded([&] { (void)read_rolling_settings(cases.section("rolling")).steps(); });
      fuzz::guarded([&] { (void)read_tyre_rolling_settings(cases.section("rolling")); });
    }
    if (cases.has_section("road")) {
      fuzz::guarded([&] { (void)make_road_profile(cases.section("road"), 0.0, 1.0); });
    }
    fuzz::guarded([&] {
      const ConfigTable output = cases.optional_section("output");
      (void)output.text("directory", "");
      (void)output.boolean("plots", true);
      output.reject_unknown_keys();
    });
  });
}
