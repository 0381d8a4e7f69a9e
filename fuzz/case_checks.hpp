#pragma once
// The readers a case file or a model file goes through before any computation: the sections'
// keys, the tyre's parameters (without building the costly tyres: the two-layer tyre's tables
// take minutes) and the rolling settings. Shared by the case_file and model_file targets.
#include <string>
#include <vector>

#include "contact/rolling_settings.hpp"
#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "fuzz_target.hpp"
#include "greens/greens_model.hpp"
#include "greens/model_factory.hpp"
#include "greens/plate_factory.hpp"
#include "greens/two_layer_factory.hpp"
#include "road/road_profile.hpp"

namespace rollnoise::fuzz {

inline void check_tyre(const ConfigTable& tyre) {
  guarded([&] {
    const std::string model = tyre.choice("model", {"sdof", "coupled_sdof", "plate", "two_layer", "tabulated"});
    if (model == "plate") {
      (void)read_plate_tyre(tyre);
    } else if (model == "two_layer") {
      (void)read_two_layer_tyre(tyre);
    } else {
      const auto built = make_greens_model(tyre);
      (void)built->name();
      (void)built->point_count();
      (void)built->contact_point_offsets();
      (void)built->fastest_rate();
    }
  });
}

// "--set" values travel in the input after a line "#--set", one a line: the mutations reach
// them too.
inline std::vector<std::string> split_overrides(std::string& text) {
  std::vector<std::string> overrides;
  const std::string marker = "\n#--set\n";
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) return overrides;
  std::string rest = text.substr(at + marker.size());
  text.resize(at + 1);
  std::size_t start = 0;
  while (start <= rest.size()) {
    const std::size_t end = std::min(rest.find('\n', start), rest.size());
    if (end > start) overrides.push_back(rest.substr(start, end - start));
    start = end + 1;
  }
  return overrides;
}

}  // namespace rollnoise::fuzz
