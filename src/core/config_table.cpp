#include "core/config_table.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace rollnoise {
namespace {

std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += ", ";
    out += "\"" + item + "\"";
  }
  return out;
}

}  // namespace

ConfigTable::ConfigTable(const toml::table& table, std::string source, std::string section,
                         std::shared_ptr<const Provenance> provenance,
                         std::shared_ptr<PathsOutsideCaseFolder> outside)
    : table_(&table),
      source_(std::move(source)),
      section_(std::move(section)),
      provenance_(std::move(provenance)),
      outside_(std::move(outside)) {}

std::string ConfigTable::source_of(std::string_view key) const {
  if (provenance_) {
    const std::string path = section_.empty() ? std::string(key) : section_ + "." + std::string(key);
    if (auto it = provenance_->find(path); it != provenance_->end()) return it->second;
  }
  return source_;
}

std::string ConfigTable::where(std::string_view key) const {
  if (section_.empty()) return std::string(key);
  return "[" + section_ + "] " + std::string(key);
}

void ConfigTable::fail(std::string_view key, const std::string& problem) const {
  throw InputError(source_of(key), where(key), problem);
}

void ConfigTable::note_referenced_file(std::string_view key, const ReferencedFile& found) const {
  if (!outside_) return;
  const toml::node* node = find(key);
  const auto written = node ? node->value<std::string>() : std::nullopt;
  outside_->note(where(key), source_of(key), written.value_or(found.path.string()), found);
}

const toml::node* ConfigTable::find(std::string_view key) const {
  known_.emplace(key);
  return table_->get(key);
}

bool ConfigTable::contains(std::string_view key) const { return find(key) != nullptr; }

double ConfigTable::number_at(std::string_view key, const toml::node& node) const {
  std::optional<double> value;
  if (node.is_floating_point() || node.is_integer()) value = node.value<double>();
  if (!value) fail(key, "must be a number");
  if (!std::isfinite(*value)) fail(key, "must be a finite number (got " + show(*value) + ")");
  return *value;
}

double ConfigTable::number(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) fail(key, "is required (a number)");
  return number_at(key, *node);
}

double ConfigTable::number(std::string_view key, double fallback) const {
  const toml::node* node = find(key);
  return node ? number_at(key, *node) : fallback;
}

double ConfigTable::positive(std::string_view key) const {
  const double value = number(key);
  if (!(value > 0.0)) fail(key, "must be > 0 (got " + show(value) + ")");
  return value;
}

double ConfigTable::positive(std::string_view key, double fallback) const {
  if (!contains(key)) return fallback;
  return positive(key);
}

double ConfigTable::non_negative(std::string_view key) const {
  const double value = number(key);
  if (!(value >= 0.0)) fail(key, "must be >= 0 (got " + show(value) + ")");
  return value;
}

double ConfigTable::non_negative(std::string_view key, double fallback) const {
  if (!contains(key)) return fallback;
  return non_negative(key);
}

double ConfigTable::between(std::string_view key, double lo, double hi, double fallback) const {
  const double value = number(key, fallback);
  if (!(value > lo && value < hi)) {
    fail(key, "must lie strictly between " + show(lo) + " and " + show(hi) + " (got " +
                  show(value) + ")");
  }
  return value;
}

std::int64_t ConfigTable::integer(std::string_view key, std::int64_t fallback, std::int64_t min,
                                  std::int64_t max) const {
  const toml::node* node = find(key);
  if (!node) return fallback;
  if (!node->is_integer()) fail(key, "must be an integer");
  const std::int64_t value = *node->value<std::int64_t>();
  if (value < min || value > max) {
    fail(key, "must be an integer from " + std::to_string(min) + " to " + std::to_string(max) +
                  " (got " + std::to_string(value) + ")");
  }
  return value;
}

bool ConfigTable::boolean(std::string_view key, bool fallback) const {
  const toml::node* node = find(key);
  if (!node) return fallback;
  if (!node->is_boolean()) fail(key, "must be true or false");
  return *node->value<bool>();
}

std::string ConfigTable::text(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) fail(key, "is required (a string)");
  if (!node->is_string()) fail(key, "must be a string");
  return *node->value<std::string>();
}

std::string ConfigTable::text(std::string_view key, std::string fallback) const {
  if (!contains(key)) return fallback;
  return text(key);
}

std::string ConfigTable::choice(std::string_view key,
                                const std::vector<std::string>& allowed) const {
  const toml::node* node = find(key);
  if (!node) fail(key, "is required; allowed values are " + join(allowed));
  const std::string value = text(key);
  for (const auto& item : allowed)
    if (item == value) return value;
  fail(key, "unknown value \"" + value + "\"; allowed values are " + join(allowed));
}

std::string ConfigTable::choice(std::string_view key, const std::vector<std::string>& allowed,
                                std::string fallback) const {
  if (!contains(key)) return fallback;
  return choice(key, allowed);
}

std::optional<ConfigTable> ConfigTable::subtable(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  if (!node->is_table()) fail(key, "must be a table (for example [" + section_ + "." + std::string(key) + "])");
  const std::string path = section_.empty() ? std::string(key) : section_ + "." + std::string(key);
  return ConfigTable(*node->as_table(), source_of(key), path, provenance_, outside_);
}

void ConfigTable::reject_unknown_keys() const {
  for (const auto& [key, node] : *table_) {
    if (known_.count(key.str()) == 0) {
      std::vector<std::string> allowed(known_.begin(), known_.end());
      fail(key.str(), "unknown key; allowed keys here are " + join(allowed));
    }
  }
}

}  // namespace rollnoise
