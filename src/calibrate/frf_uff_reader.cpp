#include "calibrate/frf_uff_reader.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>

#include "core/error.hpp"

namespace rollnoise {
namespace {

// ---------------------------------------------------------------------------------------------
// Units labels

struct UnitsMeaning {
  FrfQuantity quantity;
  double to_si;  // multiply the data by this for m, m/s or m/s² per N
};

// Lower case, no blanks, '²' and "**2" as "^2", 'µ' as 'u'.
std::string normalise_units(std::string_view label) {
  std::string out;
  for (std::size_t i = 0; i < label.size(); ++i) {
    const char c = label[i];
    if (c == ' ' || c == '\t') continue;
    if (label.substr(i, 2) == "\xC2\xB2") {
      out += "^2";
      ++i;
    } else if (label.substr(i, 2) == "\xC2\xB5") {
      out += 'u';
      ++i;
    } else if (label.substr(i, 3) == "**2") {
      out += "^2";
      i += 2;
    } else {
      out += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    }
  }
  return out;
}

bool is_unset(std::string_view normalised) { return normalised.empty() || normalised == "none"; }

std::string_view strip_parentheses(std::string_view s) {
  if (s.size() >= 2 && s.front() == '(' && s.back() == ')') return s.substr(1, s.size() - 2);
  return s;
}

std::optional<UnitsMeaning> motion_units(std::string_view u) {
  u = strip_parentheses(u);
  struct Entry {
    std::string_view label;
    FrfQuantity quantity;
    double to_si;
  };
  static constexpr Entry table[] = {
      {"m", FrfQuantity::receptance, 1.0},        {"mm", FrfQuantity::receptance, 1e-3},
      {"um", FrfQuantity::receptance, 1e-6},      {"m/s", FrfQuantity::mobility, 1.0},
      {"mm/s", FrfQuantity::mobility, 1e-3},      {"m/s^2", FrfQuantity::accelerance, 1.0},
      {"m/s2", FrfQuantity::accelerance, 1.0},    {"mm/s^2", FrfQuantity::accelerance, 1e-3},
      {"mm/s2", FrfQuantity::accelerance, 1e-3},  {"g", FrfQuantity::accelerance, 9.80665}};
  for (const Entry& e : table)
    if (u == e.label) return UnitsMeaning{e.quantity, e.to_si};
  return std::nullopt;
}

// The factor that turns "per <unit>" into "per N".
std::optional<double> per_force_units(std::string_view u) {
  u = strip_parentheses(u);
  if (u == "n") return 1.0;
  if (u == "kn") return 1e-3;
  return std::nullopt;
}

// Reads "(1/N)*(m/s^2)", "m/s/N", "(m/s^2)/N", "g/N"; or the numerator units alone with the
// force in the denominator's label. std::nullopt when the labels say nothing recognisable.
std::optional<UnitsMeaning> frf_units(const std::string& numerator, const std::string& denominator) {
  std::string_view motion = numerator;
  std::optional<double> per_force;
  if (motion.substr(0, 3) == "(1/") {
    const auto close = motion.find(')');
    if (close == std::string_view::npos) return std::nullopt;
    per_force = per_force_units(motion.substr(3, close - 3));
    motion = motion.substr(close + 1);
    if (!motion.empty() && motion.front() == '*') motion.remove_prefix(1);
  } else if (const auto slash = motion.rfind('/'); slash != std::string_view::npos) {
    per_force = per_force_units(motion.substr(slash + 1));
    if (per_force) motion = motion.substr(0, slash);
  }
  if (!per_force) {
    if (is_unset(denominator)) return std::nullopt;
    per_force = per_force_units(denominator);
    if (!per_force) return std::nullopt;
  }
  auto meaning = motion_units(motion);
  if (!meaning) return std::nullopt;
  meaning->to_si *= *per_force;
  return meaning;
}

// ---------------------------------------------------------------------------------------------
// Record checks

std::optional<FrfQuantity> motion_code(int code) {
  if (code == 8) return FrfQuantity::receptance;
  if (code == 11) return FrfQuantity::mobility;
  if (code == 12) return FrfQuantity::accelerance;
  return std::nullopt;
}

bool is_force_code(int code) { return code == 13 || code == 9; }

std::string record_label(const Uff58Record& r) {
  std::ostringstream s;
  s << "dataset " << r.position << " (" << (r.binary ? "58b" : "58") << ", line " << r.line << ")";
  return s.str();
}

std::string code_text(const UffAxis& axis) {
  std::ostringstream s;
  s << uff_specific_data_type_name(axis.specific_data_type) << " (specific data type " << axis.specific_data_type
    << ", units '" << axis.units << "')";
  return s.str();
}

double abscissa_to_hz(const Uff58Record& r, const std::string& source) {
  const std::string label = record_label(r) + ", record 8";
  const int type = r.abscissa_axis.specific_data_type;
  if (type != 18 && type != 0 && type != 1)
    throw InputError(source, label,
                     "the abscissa is " + code_text(r.abscissa_axis) +
                         "; an FRF's abscissa is frequency (specific data type 18)");
  const std::string units = normalise_units(r.abscissa_axis.units);
  if (is_unset(units) || units == "hz") return 1.0;
  if (units == "khz") return 1000.0;
  if (units == "rad/s") return 1.0 / (2.0 * std::numbers::pi);
  throw InputError(source, label,
                   "abscissa units '" + r.abscissa_axis.units + "' are not a frequency unit; allowed: Hz, kHz, rad/s");
}

// The quantity and the factor to SI of an FRF record.
UnitsMeaning record_quantity(const Uff58Record& r, const std::string& source, const FrfReadOptions& options,
                             std::vector<std::string>& notes) {
  const std::string label = record_label(r) + ", records 9-10";
  const UffAxis& num = r.numerator_axis;
  const UffAxis& den = r.denominator_axis;
  const std::optional<UnitsMeaning> units = frf_units(normalise_units(num.units), normalise_units(den.units));
  const auto wrong = [&](const std::string& what) {
    throw InputError(source, label,
                     what + "; calibrate fits motion over force: receptance (displacement, code 8), mobility "
                            "(velocity, 11) or accelerance (acceleration, 12) over excitation force (13)");
  };
  if (motion_code(den.specific_data_type))
    wrong("the FRF is " + code_text(num) + " over " + code_text(den) +
          ", force over motion (an impedance, dynamic stiffness or apparent mass)");

  std::optional<FrfQuantity> quantity = motion_code(num.specific_data_type);
  if (quantity) {
    if (!is_force_code(den.specific_data_type) && den.specific_data_type != 0)
      wrong("the FRF is " + code_text(num) + " over " + code_text(den));
    if (units && units->quantity != *quantity)
      throw InputError(source, label,
                       "the numerator is " + code_text(num) + " but its units say " +
                           frf_quantity_name(units->quantity) + "; the codes and units labels disagree");
  } else if (num.specific_data_type <= 1) {
    // Unknown or general: the units label decides, else the --data-type option.
    if (units) {
      quantity = units->quantity;
    } else if (options.quantity_given) {
      quantity = options.quantity;
      notes.push_back(source + ", " + record_label(r) + ": the record does not say what it holds (numerator " +
                      code_text(num) + "); read as " + frf_quantity_name(options.quantity) + " in SI units (--data-type)");
      return {options.quantity, 1.0};
    } else {
      wrong("the record does not say what it holds: the numerator is " + code_text(num) + " over " + code_text(den) +
            "; give --data-type when the data is motion over force in SI units");
    }
  } else {
    wrong("the FRF is " + code_text(num) + " over " + code_text(den));
  }
  if (options.quantity_given && *quantity != options.quantity)
    throw InputError(source, label,
                     "the record holds " + frf_quantity_name(*quantity) + " (" + code_text(num) +
                         "), but --data-type says " + frf_quantity_name(options.quantity));
  if (units) return {*quantity, units->to_si};
  const std::string n = normalise_units(num.units);
  if (!is_unset(n))
    notes.push_back(source + ", " + record_label(r) + ": units '" + num.units + "' over '" + den.units +
                    "' are not recognised; SI units (m, s, N) assumed");
  return {*quantity, 1.0};
}

// +1 when response and reference point the same way, −1 when opposite.
double direction_sign(const Uff58Record& r, const std::string& source) {
  const int a = r.response_direction;
  const int b = r.reference_direction;
  if (a == 0 || b == 0) return 1.0;
  if (std::abs(a) > 3 || std::abs(b) > 3 || std::abs(a) != std::abs(b)) {
    std::ostringstream what;
    what << "response direction " << a << " and reference direction " << b
         << " are not translations along one axis; calibrate fits the response along the force (directions "
            "±1, ±2, ±3 on the same axis, or 0 for scalar data)";
    throw InputError(source, record_label(r) + ", record 6", what.str());
  }
  return (a > 0) == (b > 0) ? 1.0 : -1.0;
}

MeasuredFrf frf_from_record(const Uff58Record& r, const std::string& source, const FrfReadOptions& options,
                            std::vector<std::string>& notes) {
  MeasuredFrf frf;
  frf.source = source;
  frf.label = record_label(r);
  if (!r.is_complex())
    throw InputError(source, frf.label + ", record 7",
                     "the FRF is " + uff_ordinate_type_name(r.ordinate_type) +
                         "; the fit needs magnitude and phase (complex data, ordinate type 5 or 6)");
  const double to_hz = abscissa_to_hz(r, source);
  const UnitsMeaning meaning = record_quantity(r, source, options, notes);
  frf.quantity = meaning.quantity;
  const double scale = meaning.to_si * direction_sign(r, source);
  frf.response_dof = UffDof{r.response_node, r.response_direction};
  frf.reference_dof = UffDof{r.reference_node, r.reference_direction};
  std::vector<double> hz(r.points);
  std::vector<std::complex<double>> values(r.points);
  for (std::size_t k = 0; k < r.points; ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    hz[k] = r.abscissa[i] * to_hz;
    values[k] = r.complex_ordinate[i] * scale;
  }
  fill_mobility(frf, hz, values, [](std::size_t k) { return "point " + std::to_string(k + 1); }, notes);
  return frf;
}

std::string dataset_list(const std::vector<int>& numbers) {
  std::string text;
  for (int n : numbers) {
    if (!text.empty()) text += ", ";
    text += std::to_string(n);
  }
  return text;
}

}  // namespace

FrfFile select_uff_frfs(const std::vector<Uff58Record>& records, const std::vector<int>& skipped_datasets,
                        const std::string& source, const FrfReadOptions& options) {
  if (records.empty()) {
    std::string problem = "holds no dataset 58 (function at nodal DOF); calibrate reads FRFs from datasets 58 and 58b";
    if (!skipped_datasets.empty()) problem += " (the file holds datasets " + dataset_list(skipped_datasets) + ")";
    throw InputError(source, "", problem);
  }
  FrfFile file;
  std::vector<const Uff58Record*> others;
  for (const Uff58Record& r : records) {
    if (r.is_frf())
      file.frfs.push_back(frf_from_record(r, source, options, file.notes));
    else
      others.push_back(&r);
  }
  if (file.frfs.empty()) {
    std::string problem = "holds no frequency response function (dataset 58, function type 4); found: ";
    for (std::size_t i = 0; i < others.size() && i < 3; ++i) problem += (i ? "; " : "") + describe_uff58(*others[i]);
    if (others.size() > 3) problem += "; and " + std::to_string(others.size() - 3) + " more";
    throw InputError(source, "", problem);
  }
  for (const Uff58Record* r : others)
    file.notes.push_back(source + ": " + record_label(*r) + " is a " + uff_function_type_name(r->function_type) +
                         " (function type " + std::to_string(r->function_type) + "), not an FRF: left out");
  if (!skipped_datasets.empty())
    file.notes.push_back(source + ": datasets " + dataset_list(skipped_datasets) +
                         " are left out (calibrate reads FRFs from datasets 58 and 58b)");
  return file;
}

FrfFile parse_uff_frfs(std::string_view bytes, const std::string& source, const FrfReadOptions& options) {
  std::vector<int> skipped;
  const std::vector<Uff58Record> records = parse_uff58(bytes, source, &skipped);
  return select_uff_frfs(records, skipped, source, options);
}

FrfFile read_uff_frfs(const std::filesystem::path& path, const FrfReadOptions& options) {
  std::vector<int> skipped;
  const std::vector<Uff58Record> records = read_uff58(path, &skipped);
  return select_uff_frfs(records, skipped, path.string(), options);
}

}  // namespace rollnoise
