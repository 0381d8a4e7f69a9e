#pragma once
// Typed, validated access to one table of a case or model file. Every lookup names the key it
// looked for, so that keys nobody asked for can be reported as unknown instead of being
// silently ignored.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/referenced_file.hpp"

namespace rollnoise {

// Where each value came from, by dotted path ("tyre.mass"): a model file or "--set". Paths
// that are not listed come from the table's own source.
using Provenance = std::map<std::string, std::string>;

class ConfigTable {
 public:
  // `outside`: where note_referenced_file() records files named outside their folder (the
  // CaseFile's list, for the summary); none for a table read on its own.
  ConfigTable(const toml::table& table, std::string source, std::string section,
              std::shared_ptr<const Provenance> provenance = nullptr,
              std::shared_ptr<PathsOutsideCaseFolder> outside = nullptr);

  const std::string& section() const noexcept { return section_; }
  // The file (or "--set") that holds `key`.
  std::string source_of(std::string_view key) const;
  // "[section] key", as used in messages.
  std::string where(std::string_view key) const;

  bool contains(std::string_view key) const;

  // Finite numbers; integers are accepted where a real is asked for.
  double number(std::string_view key) const;
  double number(std::string_view key, double fallback) const;
  double positive(std::string_view key) const;
  double positive(std::string_view key, double fallback) const;
  double non_negative(std::string_view key) const;
  double non_negative(std::string_view key, double fallback) const;
  // lo < value < hi (open interval).
  double between(std::string_view key, double lo, double hi, double fallback) const;
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t min,
                       std::int64_t max) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string text(std::string_view key) const;
  std::string text(std::string_view key, std::string fallback) const;
  // One of `allowed`; the message lists them.
  std::string choice(std::string_view key, const std::vector<std::string>& allowed) const;
  std::string choice(std::string_view key, const std::vector<std::string>& allowed,
                     std::string fallback) const;

  // The raw TOML node of a key (nullptr when absent), for values no typed lookup covers, such as
  // lists of tables; the key counts as known.
  const toml::node* raw(std::string_view key) const { return find(key); }

  // A nested table (TOML [section.key] or key.sub = …); std::nullopt when absent. A value that
  // is not a table is an InputError.
  std::optional<ConfigTable> subtable(std::string_view key) const;

  // Throws InputError for the first key in the table that no lookup asked for, listing the
  // keys that are allowed here.
  void reject_unknown_keys() const;

  // Throws InputError naming `key` with `problem` (for checks that involve several keys).
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;

  // `key` (a string) named the file `found`: listed in the run's summary when it lies outside
  // the folder it was looked up in (core/referenced_file.hpp).
  void note_referenced_file(std::string_view key, const ReferencedFile& found) const;

 private:
  const toml::node* find(std::string_view key) const;
  double number_at(std::string_view key, const toml::node& node) const;

  const toml::table* table_;
  std::string source_;
  std::string section_;
  std::shared_ptr<const Provenance> provenance_;
  std::shared_ptr<PathsOutsideCaseFolder> outside_;
  mutable std::set<std::string, std::less<>> known_;
};

}  // namespace rollnoise
