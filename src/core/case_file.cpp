#include "core/case_file.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

toml::table parse_toml_file(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path.string(), "", "file not found");
  if (fs::is_directory(path, ec)) throw InputError(path.string(), "", "is a folder, not a file");
  if (!fs::is_regular_file(path, ec)) throw InputError(path.string(), "", "is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot be opened for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_toml_text(buffer.str(), path.string());
}

toml::table parse_toml_text(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    throw InputError(source,
                     "line " + std::to_string(begin.line) + ", column " +
                         std::to_string(begin.column),
                     "malformed TOML: " + std::string(error.description()));
  }
}

fs::path resolve_referenced_file(const fs::path& referenced, const fs::path& case_file) {
  return find_referenced_file(referenced, case_file).path;
}

CaseFile::CaseFile(fs::path path, toml::table root)
    : path_(std::move(path)),
      root_(std::move(root)),
      provenance_(std::make_shared<Provenance>()),
      outside_(std::make_shared<PathsOutsideCaseFolder>()) {}

namespace {

// Reads the value of "key=value" as TOML, or as a plain string when it is not valid TOML
// (so that --set road.type=sine works without quotes).
toml::node_type parse_override_value(const std::string& text, toml::table& holder) {
  try {
    holder = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    holder = toml::table{{"v", text}};
  }
  return holder["v"].type();
}

}  // namespace

void CaseFile::apply_overrides(const std::vector<std::string>& overrides,
                               const std::string& prefix) {
  for (const auto& item : overrides) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw InputError("--set", item, "expected section.key=value");
    }
    const std::string path = item.substr(0, eq);
    toml::table holder;
    parse_override_value(item.substr(eq + 1), holder);

    // Walk (and create) the tables along the dotted path.
    toml::table* table = &root_;
    std::string full = prefix;
    std::size_t start = 0;
    while (true) {
      const auto dot = path.find('.', start);
      const std::string part = path.substr(start, dot == std::string::npos ? dot : dot - start);
      if (part.empty()) throw InputError("--set", item, "empty name in the key path");
      full += (full.empty() ? "" : ".") + part;
      if (dot == std::string::npos) {
        table->insert_or_assign(part, *holder["v"].node());
        (*provenance_)[full] = "--set " + path;
        break;
      }
      toml::node* next = table->get(part);
      if (!next) next = &table->insert_or_assign(part, toml::table{}).first->second;
      if (!next->is_table()) {
        throw InputError("--set", item, "\"" + full + "\" is a value, not a table");
      }
      table = next->as_table();
      start = dot + 1;
    }
  }
}

namespace {

// The names (without .toml) of the TOML files in `folder`, sorted; empty when it is no folder.
std::vector<std::string> toml_files_in(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return names;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".toml" && it->is_regular_file(ec)) names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Lays `overrides` over `base`: values replace values, tables are merged key by key, except a
// table that names another `type` than the base's (a different tread, say), which replaces the
// base's whole table, whose other keys would mean nothing to the new type. Keys that stay from
// `base` are recorded as coming from `base_source`.
void overlay_table(toml::table& base, const toml::table& overrides, const std::string& path,
                   const std::string& base_source, Provenance& provenance) {
  for (const auto& [k, node] : overrides) {
    toml::node* below = base.get(k.str());
    const toml::table* over_table = node.as_table();
    toml::table* base_table = below ? below->as_table() : nullptr;
    const bool same_type = over_table && base_table &&
                           (!over_table->contains("type") || !base_table->contains("type") ||
                            (*over_table)["type"].value<std::string>() == (*base_table)["type"].value<std::string>());
    if (over_table && base_table && same_type)
      overlay_table(*base_table, *over_table, path + "." + std::string(k.str()), base_source, provenance);
    else
      base.insert_or_assign(k.str(), node);
  }
  for (const auto& [k, node] : base) {
    const std::string dotted = path + "." + std::string(k.str());
    if (!overrides.contains(k.str())) provenance[dotted] = base_source;
    // A table kept from the base whose keys were not overridden came whole from the base.
    if (const toml::table* kept = node.as_table(); kept && !overrides.contains(k.str()))
      for (const auto& [inner, unused] : *kept) provenance[dotted + "." + std::string(inner.str())] = base_source;
  }
}

}  // namespace

void CaseFile::merge_library_file(const std::string& section, const std::string& key,
                                  const std::string& library_folder, const std::string& kind) {
  toml::table* table = root_[section].as_table();
  if (!table) return;
  const toml::node* ref = table->get(key);
  if (!ref) return;
  const std::string dotted = section + "." + key;
  const std::string where = "[" + section + "] " + key;
  const auto provenance = provenance_->find(dotted);
  const std::string key_source = provenance == provenance_->end() ? name() : provenance->second;
  if (!ref->is_string()) {
    throw InputError(key_source, where, "must be a string (the path of a " + kind + " file, such as \"" +
                                            library_folder + "/NAME.toml\")");
  }
  const std::string named = *ref->value<std::string>();
  const ReferencedFile found = find_referenced_file(named, path_);
  const fs::path& file_path = found.path;
  std::error_code ec;
  if (!fs::exists(file_path, ec)) {
    // List what there is: in the library folder nearest the case file (models/surfaces in its
    // folder or one above it), else the one found like any referenced file, else the folder
    // the path points into.
    fs::path folder;
    for (fs::path dir = path_.parent_path(); !dir.empty(); dir = dir.parent_path()) {
      if (fs::is_directory(dir / library_folder, ec)) {
        folder = dir / library_folder;
        break;
      }
      if (dir == dir.parent_path()) break;
    }
    if (folder.empty()) folder = resolve_referenced_file(library_folder, path_);
    if (!fs::is_directory(folder, ec)) folder = file_path.parent_path();
    const std::vector<std::string> available = toml_files_in(folder);
    std::string problem = "no " + kind + " file \"" + named + "\": file not found (tried " + file_path.string() + ")";
    if (!available.empty()) {
      problem += "; the " + kind + " files in " + folder.string() + " are ";
      for (std::size_t i = 0; i < available.size(); ++i) problem += (i ? ", " : "") + available[i];
    }
    throw InputError(key_source, where, problem);
  }
  toml::table library = parse_toml_file(file_path);
  outside_->note(where, key_source, named, found);
  (section == "tyre" ? tyre_file_ : surface_file_) = named;
  // Keys beside `key` override the library file's, key by key also inside tables such as
  // [tyre.tread] (so `--set tyre.tread.stiffness_per_area=…` keeps the file's tread type).
  table->erase(key);
  overlay_table(library, *table, section, file_path.string(), *provenance_);
  root_.insert_or_assign(section, std::move(library));
}

CaseFile CaseFile::load(const fs::path& path, const std::vector<std::string>& overrides) {
  return from_table(path, parse_toml_file(path), overrides);
}

CaseFile CaseFile::from_table(const fs::path& path, toml::table root, const std::vector<std::string>& overrides) {
  CaseFile file(path, std::move(root));
  // Overrides first, so that --set tyre.file=... picks the model file (and --set
  // road.surface=... the surface), and so that --set road.key=... overrides the library file.
  file.apply_overrides(overrides, "");
  file.merge_library_file("tyre", "file", "models/tyres", "model");
  file.merge_library_file("road", "surface", "models/surfaces", "surface");
  return file;
}

CaseFile CaseFile::load_model(const fs::path& path, const std::vector<std::string>& overrides) {
  return model_from_table(path, parse_toml_file(path), overrides);
}

CaseFile CaseFile::model_from_table(const fs::path& path, toml::table root, const std::vector<std::string>& overrides) {
  CaseFile file(path, std::move(root));
  file.apply_overrides(overrides, "");
  return file;
}

bool CaseFile::has_section(std::string_view name) const {
  const toml::node* node = root_.get(name);
  return node && node->is_table();
}

ConfigTable CaseFile::section(std::string_view name) const {
  const toml::node* node = root_.get(name);
  if (!node) throw InputError(this->name(), "[" + std::string(name) + "]", "section is required");
  if (!node->is_table()) {
    throw InputError(this->name(), std::string(name), "must be a table ([" + std::string(name) + "])");
  }
  return ConfigTable(*node->as_table(), this->name(), std::string(name), provenance_, outside_);
}

ConfigTable CaseFile::optional_section(std::string_view name) const {
  if (!root_.get(name)) return ConfigTable(empty_, this->name(), std::string(name), provenance_, outside_);
  return section(name);
}

ConfigTable CaseFile::top() const { return ConfigTable(root_, name(), "", provenance_, outside_); }

void CaseFile::reject_unknown_sections(const std::vector<std::string>& allowed) const {
  for (const auto& [key, node] : root_) {
    bool ok = false;
    for (const auto& a : allowed) ok = ok || a == key.str();
    if (!ok) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "[" : ", [") + a + "]";
      throw InputError(name(), std::string(key.str()), "unknown section; allowed sections are " + list);
    }
  }
}

}  // namespace rollnoise
