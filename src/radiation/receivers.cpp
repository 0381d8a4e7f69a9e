#include "radiation/receivers.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "core/config_table.hpp"
#include "core/error.hpp"

namespace rollnoise {

bool is_standard_receiver(const std::string& name) {
  return name == "cpx_front" || name == "cpx_rear" || name == "spb";
}

Receiver standard_receiver(const std::string& name, double tyre_width) {
  const double beside = 0.5 * tyre_width + 0.2;  // 0.2 m out from the sidewall
  if (name == "cpx_front") return {name, {0.2, beside, 0.1}};
  if (name == "cpx_rear") return {name, {-0.2, beside, 0.1}};
  if (name == "spb") return {name, {0.0, 7.5, 1.2}};
  throw std::invalid_argument("no standard receiver \"" + name + "\"");
}

std::vector<Receiver> read_receivers(const ConfigTable& radiation, double tyre_width) {
  std::vector<Receiver> out;
  const toml::node* node = nullptr;
  if (radiation.contains("receivers")) node = radiation.raw("receivers");
  if (!node) {
    for (const char* name : {"cpx_front", "cpx_rear", "spb"}) out.push_back(standard_receiver(name, tyre_width));
    return out;
  }
  const toml::array* list = node->as_array();
  if (!list || list->empty()) {
    radiation.fail("receivers", "must be a non-empty list of names (\"cpx_front\", \"cpx_rear\", \"spb\") or "
                                "tables {name, x, y, z} (m)");
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    const std::string where = "item " + std::to_string(i + 1);
    Receiver r;
    if (const auto* text = item.as_string()) {
      if (!is_standard_receiver(text->get())) {
        radiation.fail("receivers", where + ": unknown receiver \"" + text->get() +
                                        "\"; allowed names are \"cpx_front\", \"cpx_rear\", \"spb\", or a table {name, x, y, z}");
      }
      r = standard_receiver(text->get(), tyre_width);
    } else if (const auto* table = item.as_table()) {
      const ConfigTable t(*table, radiation.source_of("receivers"), radiation.section() + ".receivers[" + std::to_string(i + 1) + "]");
      r.name = t.text("name");
      r.position = {t.number("x"), t.number("y"), t.number("z")};
      t.reject_unknown_keys();
      if (!(r.position.z() > 0.0)) t.fail("z", "must be above the road (> 0 m)");
      if (r.name.empty() || r.name.find_first_of("/\\:*?\"<>|") != std::string::npos) {
        t.fail("name", "must be a plain file name (it names <receiver>.wav)");
      }
    } else {
      radiation.fail("receivers", where + ": must be a name or a table {name, x, y, z}");
    }
    if (!names.insert(r.name).second) radiation.fail("receivers", where + ": \"" + r.name + "\" appears twice");
    out.push_back(r);
  }
  return out;
}

}  // namespace rollnoise
