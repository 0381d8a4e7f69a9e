#include "study/study_file.hpp"

#include <algorithm>
#include <cctype>
#include <limits>
#include <set>

#include "core/case_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

// Keys the case readers know beyond those a base case shows (tyre and road keys depend on the
// model and road type: those are taken from the base case and its library files). tests/docs/
// test_key_reference.cpp fails when a reader takes a [rolling], [radiation] or [output] key missing here.
const std::vector<std::string>& known_keys(const std::string& section) {
  static const std::vector<std::string> rolling = {"speed", "duration", "time_step", "static_load", "history",
                                                  "discretisation", "points_circumferential", "points_lateral",
                                                  "contact_window", "band_top", "road_sampling", "contact_law"};
  static const std::vector<std::string> radiation = {
      "enabled",      "receivers",      "max_frequency",         "anchor_spacing",         "mesh_around",
      "mesh_across",  "sidewall_rings", "contact_refinement",    "threads",                "points_per_wavelength",
      "combined_sources_above", "geometry", "cache_limit", "air_pumping"};
  static const std::vector<std::string> output = {"plots", "wav", "audio_rate", "wav_duration", "fields"};
  static const std::vector<std::string> tyre = {"file", "model"};
  static const std::vector<std::string> road = {"surface", "type"};
  static const std::vector<std::string> none;
  if (section == "rolling") return rolling;
  if (section == "radiation") return radiation;
  if (section == "output") return output;
  if (section == "tyre") return tyre;
  if (section == "road") return road;
  return none;
}

std::string label_of(const toml::node& value) {
  if (const auto* s = value.as_string()) return s->get();
  if (const auto* i = value.as_integer()) return std::to_string(i->get());
  if (const auto* d = value.as_floating_point()) return format_number(d->get());
  if (const auto* b = value.as_boolean()) return b->get() ? "true" : "false";
  return "?";  // dates and times: the readers take none
}

// The keys a case section may take: those the base case (with its library files) holds, and
// those the readers know.
std::set<std::string> allowed_keys(const CaseFile& base, const std::string& section) {
  std::set<std::string> keys(known_keys(section).begin(), known_keys(section).end());
  if (const toml::table* table = base.root()[section].as_table())
    for (const auto& [k, node] : *table) keys.insert(std::string(k.str()));
  return keys;
}

std::vector<StudyParameter> read_parameters(const toml::table& study, const std::string& table_name, bool lists,
                                            const fs::path& path, const CaseFile& base) {
  std::vector<StudyParameter> out;
  const toml::node* node = study.get(table_name);
  if (!node) return out;
  const std::string source = path.string();
  if (!node->is_table()) throw InputError(source, table_name, "must be a table of section.key entries");
  static const std::vector<std::string> sections = {"tyre", "road", "rolling", "radiation", "output"};
  for (const auto& [section_name, section_node] : *node->as_table()) {
    const std::string section(section_name.str());
    if (std::find(sections.begin(), sections.end(), section) == sections.end())
      throw InputError(source, "[" + table_name + "] " + section,
                       "unknown case section; keys are section.key with section one of tyre, road, rolling, radiation, "
                       "output");
    if (!section_node.is_table())
      throw InputError(source, "[" + table_name + "] " + section, "must be written section.key = value");
    const std::set<std::string> allowed = allowed_keys(base, section);
    for (const auto& [key_name, value] : *section_node.as_table()) {
      StudyParameter p{{section, std::string(key_name.str())}, {}, {}};
      const std::string where = "[" + table_name + "] " + p.key.dotted();
      if (!allowed.count(p.key.key)) {
        std::string known;
        for (const std::string& k : allowed) known += (known.empty() ? "" : ", ") + k;
        throw InputError(source, where, "unknown key of [" + section + "]; known: " + known);
      }
      if (section == "output" && p.key.key == "directory")
        throw InputError(source, where, "each case writes to cases/<id>/ of the study's folder");
      if (lists) {
        const toml::array* list = value.as_array();
        if (!list) throw InputError(source, where, "must be a list of values, such as [13.889, 22.222]");
        if (list->empty()) throw InputError(source, where, "is an empty list: give at least one value");
        for (const toml::node& v : *list) {
          if (v.is_table() || v.is_array_of_tables())
            throw InputError(source, where, "values must be numbers, strings or booleans");
          p.values.push_back(v);
        }
      } else {
        p.values.push_back(value);
      }
      for (std::size_t i = 0; i < p.values.size(); ++i) {
        const toml::node& v = *p.values.get(i);
        p.labels.push_back(label_of(v));
        if (p.key.names_file()) {
          const auto* text = v.as_string();
          if (!text) throw InputError(source, where, "must be the path of a TOML file (a string)");
          const fs::path file = resolve_referenced_file(text->get(), path);
          std::error_code ec;
          if (!fs::is_regular_file(file, ec)) throw InputError(source, where, "no file \"" + text->get() + "\" (tried " + file.string() + ")");
          p.labels.back() = fs::path(text->get()).stem().string();
          p.values.replace(p.values.cbegin() + static_cast<std::ptrdiff_t>(i), fs::weakly_canonical(file).string());
        }
      }
      out.push_back(std::move(p));
    }
  }
  return out;
}

}  // namespace

std::size_t StudySpec::case_count() const {
  std::size_t n = 1;
  for (const StudyParameter& p : varied) {
    if (p.values.size() > std::numeric_limits<std::size_t>::max() / n) return std::numeric_limits<std::size_t>::max();
    n *= p.values.size();
  }
  return n;
}

StudySpec read_study_file(const fs::path& path) {
  const toml::table root = parse_toml_file(path);
  const std::string source = path.string();
  for (const auto& [k, node] : root) {
    const std::string name(k.str());
    if (name != "study" && name != "set" && name != "vary")
      throw InputError(source, name, "unknown section; a study file has [study], [set] and [vary]");
  }
  const toml::table* study = root["study"].as_table();
  if (!study) throw InputError(source, "study", "missing: [study] with name and case");
  for (const auto& [k, node] : *study) {
    const std::string name(k.str());
    if (name != "name" && name != "case" && name != "reference_surface")
      throw InputError(source, "[study] " + name, "unknown key; [study] has name, case and reference_surface");
  }
  StudySpec spec;
  spec.file = path;
  const auto name = (*study)["name"].value<std::string>();
  if (!name || name->empty()) throw InputError(source, "[study] name", "missing: a name for the study (a string)");
  for (char c : *name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      throw InputError(source, "[study] name", "may hold letters, digits, '_', '-' and '.' only (it names a folder)");
  spec.name = *name;
  const auto base = (*study)["case"].value<std::string>();
  if (!base) throw InputError(source, "[study] case", "missing: the base case file (a string, relative to the study file)");
  spec.base_case = fs::weakly_canonical(resolve_referenced_file(*base, path));
  const CaseFile base_case = CaseFile::load(spec.base_case);
  spec.fixed = read_parameters(root, "set", false, path, base_case);
  spec.varied = read_parameters(root, "vary", true, path, base_case);
  if (spec.varied.empty()) throw InputError(source, "vary", "missing: [vary] with at least one list of values");
  for (const StudyParameter& f : spec.fixed)
    for (const StudyParameter& v : spec.varied)
      if (f.key.dotted() == v.key.dotted())
        throw InputError(source, "[set] " + f.key.dotted(), "is also in [vary]: give it in one of them");
  if (const auto reference = (*study)["reference_surface"].value<std::string>()) {
    const auto surfaces = std::find_if(spec.varied.begin(), spec.varied.end(),
                                       [](const StudyParameter& p) { return p.key.dotted() == "road.surface"; });
    const fs::path file = fs::weakly_canonical(resolve_referenced_file(*reference, path));
    bool listed = false;
    if (surfaces != spec.varied.end())
      for (const toml::node& v : surfaces->values) listed = listed || v.value<std::string>() == file.string();
    if (!listed)
      throw InputError(source, "[study] reference_surface", "must be one of the [vary] road.surface list");
    spec.reference_surface = file.string();
  }
  return spec;
}

}  // namespace rollnoise
