#pragma once
// Loading case and model files: TOML parsing with located errors, `[tyre] file = ...`
// resolution, and `--set section.key=value` overrides, with the origin of every value kept
// so that messages name the right file.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "core/referenced_file.hpp"

namespace rollnoise {

// Parses a TOML file; a missing, unreadable or malformed file is an InputError naming the
// file (and line and column for syntax errors).
toml::table parse_toml_file(const std::filesystem::path& path);
// Parses TOML text; `source` names it in messages (a malformed text is an InputError naming the
// line and column, as for a file).
toml::table parse_toml_text(const std::string& text, const std::string& source);

class CaseFile {
 public:
  // Loads `path`, applies `overrides` ("section.key=value"; the value is read as TOML, and as
  // a plain string if it is not valid TOML), then merges the library files: the model file
  // named by `[tyre] file` and the surface file named by `[road] surface` (each holds the keys
  // of its table at its top level; keys given beside `file` / `surface`, in the case or by
  // --set, override the library file's). Every key keeps the file it came from, for messages.
  // A library file that is not found is an InputError naming the key, the path tried and the
  // files in its folder (or in models/tyres, models/surfaces).
  static CaseFile load(const std::filesystem::path& path,
                       const std::vector<std::string>& overrides = {});
  // A case assembled in memory (a study's case): `root` as if read from `path` (whose folder
  // the library files it names are found from), then merged as load() merges them.
  // A case assembled in memory (a study's case, a case given to the Python module as text or a
  // dict): `root` as if read from `path` (whose folder the library files it names are found
  // from; a bare name: the current folder), with `overrides` applied, then merged as load()
  // merges them.
  static CaseFile from_table(const std::filesystem::path& path, toml::table root,
                             const std::vector<std::string>& overrides = {});
  // A model file: the keys of a [tyre] table at the top level.
  static CaseFile load_model(const std::filesystem::path& path,
                             const std::vector<std::string>& overrides = {});
  // A model file assembled in memory, as from_table for a case.
  static CaseFile model_from_table(const std::filesystem::path& path, toml::table root,
                                   const std::vector<std::string>& overrides = {});

  const std::filesystem::path& path() const noexcept { return path_; }
  std::string name() const { return path_.string(); }
  const toml::table& root() const noexcept { return root_; }

  bool has_section(std::string_view name) const;
  // A top-level table; a missing required one is an InputError.
  ConfigTable section(std::string_view name) const;
  // An empty table when absent.
  ConfigTable optional_section(std::string_view name) const;
  // The whole file as one table (for model files, whose keys sit at the top level).
  ConfigTable top() const;
  // Rejects top-level keys or tables other than `allowed`.
  void reject_unknown_sections(const std::vector<std::string>& allowed) const;

  // The files this case named (its library files, and those its tables' readers resolved so
  // far) that lie outside the folder they were looked up in, through ".." or a symlink: for
  // the summary ("paths_outside_case_folder").
  std::vector<PathOutsideCaseFolder> paths_outside_folder() const { return outside_->entries(); }

  // The library files merged in, as named (after --set): `[tyre] file` and `[road] surface`
  // ("" when the case gave its keys inline), for the summary.
  const std::string& tyre_file() const noexcept { return tyre_file_; }
  const std::string& surface_file() const noexcept { return surface_file_; }

 private:
  CaseFile(std::filesystem::path path, toml::table root);
  void apply_overrides(const std::vector<std::string>& overrides, const std::string& prefix);
  // Replaces [section] by the TOML file its `key` names, with the section's other keys on top.
  void merge_library_file(const std::string& section, const std::string& key, const std::string& library_folder,
                          const std::string& kind);

  std::filesystem::path path_;
  toml::table root_;
  toml::table empty_;
  std::shared_ptr<Provenance> provenance_;
  std::shared_ptr<PathsOutsideCaseFolder> outside_;
  std::string tyre_file_, surface_file_;
};

// find_referenced_file(...).path (core/referenced_file.hpp): the file a case file names.
std::filesystem::path resolve_referenced_file(const std::filesystem::path& referenced,
                                              const std::filesystem::path& case_file);

}  // namespace rollnoise
