#include "study/study_cases.hpp"

#include <cctype>
#include <map>
#include <sstream>

#include "core/case_file.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

std::string safe_name(const std::string& text) {
  std::string out;
  for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return out;
}

void apply(toml::table& root, const StudyKey& key, const toml::node& value) {
  if (key.replaces_table()) {
    root.insert_or_assign(key.section, toml::table{{key.key, value}});
    return;
  }
  toml::node* section = root.get(key.section);
  if (!section || !section->is_table()) section = &root.insert_or_assign(key.section, toml::table{}).first->second;
  section->as_table()->insert_or_assign(key.key, value);
}

// A library path of the base case, made absolute (found from the base case's folder).
void make_absolute(toml::table& root, const std::string& section, const std::string& key, const fs::path& base) {
  toml::table* table = root[section].as_table();
  if (!table) return;
  if (const auto text = (*table)[key].value<std::string>())
    table->insert_or_assign(key, fs::weakly_canonical(resolve_referenced_file(*text, base)).string());
}

}  // namespace

std::vector<StudyCase> study_cases(const StudySpec& spec) {
  std::vector<StudyCase> out;
  const std::size_t count = spec.case_count();
  std::map<std::string, std::size_t> seen;
  for (std::size_t index = 0; index < count; ++index) {
    StudyCase c;
    c.index = index;
    c.choice.resize(spec.varied.size());
    std::size_t rest = index;
    for (std::size_t k = spec.varied.size(); k-- > 0;) {
      c.choice[k] = rest % spec.varied[k].values.size();
      rest /= spec.varied[k].values.size();
    }
    for (std::size_t k = 0; k < spec.varied.size(); ++k) {
      const StudyParameter& p = spec.varied[k];
      c.labels.push_back(p.labels[c.choice[k]]);
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of string + string.
      if (k) c.id += '_';
      std::string part = p.key.key;
      part += '-';
      part += p.labels[c.choice[k]];
      c.id += safe_name(part);
    }
    // Two values with the same label (two surfaces of one name in different folders).
    if (const std::size_t n = seen[c.id]++; n > 0) {
      c.id += '_';
      c.id += std::to_string(n + 1);
    }
    out.push_back(std::move(c));
  }
  return out;
}

toml::table study_case_table(const StudySpec& spec, const StudyCase& c) {
  toml::table root = parse_toml_file(spec.base_case);
  make_absolute(root, "tyre", "file", spec.base_case);
  make_absolute(root, "road", "surface", spec.base_case);
  if (toml::table* output = root["output"].as_table()) output->erase("directory");
  // Table replacements first, so that keys set beside them stay.
  for (int pass = 0; pass < 2; ++pass) {
    for (const StudyParameter& p : spec.fixed)
      if (p.key.replaces_table() == (pass == 0)) apply(root, p.key, *p.values.get(0));
    for (std::size_t k = 0; k < spec.varied.size(); ++k)
      if (spec.varied[k].key.replaces_table() == (pass == 0)) apply(root, spec.varied[k].key, *spec.varied[k].values.get(c.choice[k]));
  }
  return root;
}

std::string study_case_text(const toml::table& table) {
  std::ostringstream text;
  text << table << '\n';
  return text.str();
}

CaseFile study_case_file(const StudySpec& spec, const toml::table& table) {
  return CaseFile::from_table(spec.base_case, table);
}

}  // namespace rollnoise
