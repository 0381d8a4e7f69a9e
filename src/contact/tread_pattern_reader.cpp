#include "contact/tread_pattern_reader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/height_map_surface.hpp"

namespace rollnoise {
namespace {

std::string metres(double v) { return format_number(v) + " m"; }

std::vector<double> read_pitch_sequence(const ConfigTable& pattern) {
  const std::string allowed = "a list of relative pitch lengths, each a number > 0, such as [1.0, 1.2, 0.8]";
  const toml::array* list = pattern.raw("pitch_sequence")->as_array();
  if (list == nullptr || list->empty()) pattern.fail("pitch_sequence", "must be " + allowed);
  std::vector<double> lengths;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    double value = 0.0;
    if (const auto* f = item.as_floating_point()) value = f->get();
    else if (const auto* n = item.as_integer()) value = static_cast<double>(n->get());
    else pattern.fail("pitch_sequence", "item " + std::to_string(i + 1) + " is not a number; must be " + allowed);
    if (!(value > 0.0 && std::isfinite(value)))
      pattern.fail("pitch_sequence", "item " + std::to_string(i + 1) + " is " + format_number(value) + "; must be " + allowed);
    lengths.push_back(value);
  }
  return lengths;
}

std::vector<TreadRib> read_ribs(const ConfigTable& pattern, double tread_width) {
  const std::string allowed = "a list of tables {position, width, depth} (m; position from the tread's centre line)";
  const toml::array* list = pattern.raw("ribs")->as_array();
  if (list == nullptr) pattern.fail("ribs", "must be " + allowed);
  std::vector<TreadRib> ribs;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* item = list->get(i)->as_table();
    if (item == nullptr) pattern.fail("ribs", "item " + std::to_string(i + 1) + " is not a table; must be " + allowed);
    const ConfigTable t(*item, pattern.source_of("ribs"), pattern.section() + ".ribs[" + std::to_string(i + 1) + "]");
    TreadRib rib;
    rib.position = t.number("position");
    rib.width = t.positive("width");
    rib.depth = t.non_negative("depth");
    t.reject_unknown_keys();
    if (std::abs(rib.position) + 0.5 * rib.width > 0.5 * tread_width * (1.0 + 1e-9))
      t.fail("position", "puts the groove (" + metres(rib.position - 0.5 * rib.width) + " to " +
                             metres(rib.position + 0.5 * rib.width) + ") outside the tread: it must lie within ±" +
                             metres(0.5 * tread_width) + " (half the tread_width) of the centre line");
    ribs.push_back(rib);
  }
  return ribs;
}

// A height map read as a road's (CSV or HDF5), checked to go once around the tread and across it.
TreadHeightMap read_map(const ConfigTable& pattern, double circumference, double tread_width) {
  const std::string name = pattern.text("file");
  if (name.empty()) pattern.fail("file", "must name a tread height map (CSV with columns x, y, z in m, or HDF5)");
  const ReferencedFile found = find_referenced_file(name, pattern.source_of("file"));
  pattern.note_referenced_file("file", found);
  // No run range to cover (x_max < x_min): the extent is checked here against the tyre.
  const HeightMapSurface surface(found.path, 0.0, -1.0, 0.0);
  const std::vector<double>& x = surface.x_lines();
  const std::vector<double>& y = surface.y_lines();
  const std::size_t nx = x.size();
  const double spacing = (x.back() - x.front()) / static_cast<double>(nx - 1);
  const std::string expected = "x from 0 to 2πR − Δx on N lines Δx = 2πR/N apart once around the tyre (2πR = " +
                               metres(circumference) + "; at this map's Δx = " + metres(spacing) + ", to " +
                               metres(circumference - spacing) + ") and y across the tread from " +
                               metres(-0.5 * tread_width) + " to " + metres(0.5 * tread_width);
  const std::string covers = "the map " + found.path.string() + " covers x from " + metres(x.front()) + " to " +
                             metres(x.back()) + " and y from " + metres(y.front()) + " to " + metres(y.back());
  constexpr double tolerance = 1e-4;  // relative, as CSV numbers are written to a few digits
  if (std::abs(x.front()) > tolerance * spacing ||
      std::abs(static_cast<double>(nx) * spacing - circumference) > tolerance * circumference ||
      y.front() > -0.5 * tread_width * (1.0 - 1e-9) || y.back() < 0.5 * tread_width * (1.0 - 1e-9))
    pattern.fail("file", covers + "; a tread map must give " + expected);
  TreadHeightMap map;
  map.lines_around = nx;
  map.y = y;
  map.z.resize(nx * y.size());
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < y.size(); ++j) {
      const double z = surface.height(x[i], y[j]);
      if (z > 0.0)
        pattern.fail("file", "the map " + found.path.string() + " has z = " + metres(z) + " at (x, y) = (" + metres(x[i]) +
                                 ", " + metres(y[j]) + "): tread heights must be <= 0 (0 is the block surface, grooves are negative)");
      map.z[i * y.size() + j] = z;
    }
  return map;
}

}  // namespace

std::optional<TreadPattern> read_tread_pattern(const ConfigTable& tyre, double radius, double tread_width) {
  const std::optional<ConfigTable> table = tyre.subtable("pattern");
  if (!table) return std::nullopt;
  const ConfigTable& pattern = *table;
  const double circumference = 2.0 * std::numbers::pi * radius;
  TreadPatternGeometry g;
  const bool lateral = pattern.contains("pitches") || pattern.contains("pitch_sequence");
  if (pattern.contains("file")) {
    for (const char* other : {"pitches", "pitch_sequence", "groove_width", "groove_depth", "groove_angle", "ribs"})
      if (pattern.contains(other))
        pattern.fail(other, "cannot be given with file: a tread map holds the whole pattern; give either file or the "
                            "grooves (pitches or pitch_sequence with groove_width and groove_depth, ribs)");
    g.map = read_map(pattern, circumference, tread_width);
  } else {
    if (!lateral)
      for (const char* key : {"groove_width", "groove_depth", "groove_angle"})
        if (pattern.contains(key)) pattern.fail(key, "applies to lateral grooves: give pitches or pitch_sequence too");
    if (!lateral && !pattern.contains("ribs"))
      tyre.fail("pattern", "needs lateral grooves (pitches or pitch_sequence, with groove_width and groove_depth), "
                           "circumferential grooves (ribs) or a tread map (file)");
    if (pattern.contains("pitches") && pattern.contains("pitch_sequence"))
      pattern.fail("pitch_sequence", "cannot be given with pitches: pitches = N gives N equal pitch lengths, "
                                     "pitch_sequence the relative length of each");
    if (lateral) {
      if (pattern.contains("pitches"))
        g.pitch_lengths.assign(static_cast<std::size_t>(pattern.integer("pitches", 1, 1, 10000)), 1.0);
      else
        g.pitch_lengths = read_pitch_sequence(pattern);
      const double degrees = pattern.number("groove_angle", 0.0);
      if (!(std::abs(degrees) < 80.0))
        pattern.fail("groove_angle", "is " + format_number(degrees) + "; must lie between -80 and 80 degrees from the lateral");
      g.groove_angle = degrees * std::numbers::pi / 180.0;
      g.groove_width = pattern.positive("groove_width");
      g.groove_depth = pattern.non_negative("groove_depth");
      double total = 0.0;
      for (double l : g.pitch_lengths) total += l;
      const double shortest = circumference * *std::min_element(g.pitch_lengths.begin(), g.pitch_lengths.end()) / total;
      const double along = g.groove_width / std::cos(g.groove_angle);
      if (!(along < shortest))
        pattern.fail("groove_width", "is " + metres(g.groove_width) + " (" + metres(along) +
                                         " along the circumference at groove_angle), not less than the shortest pitch, " +
                                         metres(shortest) + " (2πR = " + metres(circumference) +
                                         " over the pitches): a groove must be narrower than a pitch");
    }
    if (pattern.contains("ribs")) g.ribs = read_ribs(pattern, tread_width);
  }
  pattern.reject_unknown_keys();
  return TreadPattern(std::move(g), circumference);
}

}  // namespace rollnoise
