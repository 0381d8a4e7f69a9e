#include "calibrate/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <ceres/ceres.h>

#include "calibrate/band_weights.hpp"
#include "calibrate/frf_residual.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

std::string hz_text(double hz) {
  std::ostringstream s;
  s.precision(4);
  s << hz;
  return s.str();
}

std::string list(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) {
    if (!text.empty()) text += ", ";
    text += n;
  }
  return text;
}

// --fit and --transducer-mass as a FitLayout.
FitLayout make_layout(const CalibrationModel& model, const CalibrationSettings& settings) {
  FitLayout layout;
  layout.parameters = model.parameters();
  layout.transducer_mass = settings.transducer_mass;
  if (!(settings.transducer_mass >= 0.0) || !std::isfinite(settings.transducer_mass))
    throw InputError("--transducer-mass", "", "must be a mass >= 0 kg");
  std::vector<std::string> allowed;
  for (const auto& p : layout.parameters) allowed.push_back(p.name);
  allowed.push_back("transducer_mass");
  const std::vector<std::string> names = settings.free.empty() ? model.default_free_parameters() : settings.free;
  for (const std::string& name : names) {
    if (name == "transducer_mass") {
      if (layout.fit_transducer_mass) throw InputError("--fit", name, "is named twice");
      if (!(settings.transducer_mass > 0.0))
        throw InputError("--fit", name,
                         "is fitted in log space and needs a starting value: give --transducer-mass KG (> 0)");
      layout.fit_transducer_mass = true;
      continue;
    }
    const std::ptrdiff_t index = model.index_of(name);
    if (index < 0)
      throw InputError("--fit", name,
                       "is not a parameter of the " + model.name() + " model that calibrate can fit; allowed: " +
                           list(allowed));
    const auto k = static_cast<std::size_t>(index);
    if (std::find(layout.free.begin(), layout.free.end(), k) != layout.free.end())
      throw InputError("--fit", name, "is named twice");
    const FitParameter& p = layout.parameters[k];
    if (p.log_scale && !(p.value > 0.0))
      throw InputError("--fit", name,
                       "is " + format_number(p.value) +
                           " in the model file; it is fitted in log space from there, so give it a positive "
                           "starting value in the model file");
    layout.free.push_back(k);
  }
  if (layout.free.empty() && !layout.fit_transducer_mass)
    throw InputError("--fit", "", "names no parameter to fit; allowed: " + list(allowed));
  return layout;
}

// Lower and upper bounds of each unknown, in fit coordinates.
void unknown_bounds(const FitLayout& layout, std::vector<double>& lower, std::vector<double>& upper) {
  lower.clear();
  upper.clear();
  for (std::size_t k : layout.free) {
    const FitParameter& p = layout.parameters[k];
    lower.push_back(p.log_scale ? std::log(p.lower) : p.lower);
    upper.push_back(p.log_scale ? std::log(p.upper) : p.upper);
  }
  if (layout.fit_transducer_mass) {
    const FitParameter m = log_parameter("transducer_mass", "kg", layout.transducer_mass);
    lower.push_back(std::log(m.lower));
    upper.push_back(std::log(m.upper));
  }
}

// A uniform number in [0, 1) from 53 bits of the generator: the same on every platform
// (std::uniform_real_distribution is not specified bit for bit).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11U) * 0x1.0p-53; }

// The starts: the model file's values (clamped into the bounds), then draws within a factor of
// ten of them, log-uniform (uniform within ±0.5 for parameters fitted linearly).
std::vector<std::vector<double>> starting_points(const FitLayout& layout, const CalibrationSettings& settings) {
  std::vector<double> lower, upper;
  unknown_bounds(layout, lower, upper);
  std::vector<double> values;
  for (const auto& p : layout.parameters) values.push_back(p.value);
  const std::vector<double> x0 = layout.unknowns_of(values, layout.transducer_mass);
  std::mt19937_64 rng(settings.seed);
  std::vector<std::vector<double>> starts;
  for (int s = 0; s < std::max(1, settings.starts); ++s) {
    std::vector<double> x = x0;
    for (std::size_t j = 0; j < x.size(); ++j) {
      const bool linear = j < layout.free.size() && !layout.parameters[layout.free[j]].log_scale;
      const double spread = linear ? 0.5 : std::log(10.0);
      if (s > 0) {
        const double lo = std::max(lower[j], x0[j] - spread);
        const double hi = std::min(upper[j], x0[j] + spread);
        x[j] = lo + (hi - lo) * uniform(rng);
      }
      x[j] = std::clamp(x[j], lower[j], upper[j]);
    }
    starts.push_back(std::move(x));
  }
  return starts;
}

struct PreparedFrf {
  FittedFrf out;
  std::unique_ptr<ReceptanceFunction> transfer;
  std::unique_ptr<ReceptanceFunction> at_response;  // only for transfer FRFs with mass loading
};

FrfPoints frf_points(const CalibrationModel& model, const MeasuredFrf& frf) {
  if (frf.response.has_value() != frf.excitation.has_value()) {
    throw InputError(frf.source, frf.label,
                     std::string("gives the ") + (frf.response ? "response" : "excitation") +
                         " position but not the " + (frf.response ? "excitation" : "response") + " position; give both");
  }
  if (frf.response) return {*frf.response, *frf.excitation};
  if (model.needs_positions())
    throw InputError(frf.source, frf.label,
                     "a " + model.name() +
                         " FRF needs the response and excitation positions (x along the circumference, y across "
                         "the belt from one edge, in m): comment lines '# response_x = …', '# response_y = …', "
                         "'# excitation_x = …', '# excitation_y = …' in a CSV file, or --response X,Y "
                         "--excitation X,Y (--node N=X,Y for UFF nodes)");
  return {};  // the first contact point
}

PreparedFrf prepare(const CalibrationModel& model, const MeasuredFrf& frf, const FitLayout& layout, double lo,
                    double hi, const std::string& band_text) {
  PreparedFrf prepared;
  FittedFrf& out = prepared.out;
  out.name = frf.name();
  out.points = frf_points(model, frf);
  try {
    prepared.transfer = model.receptance(out.points);
    const bool point = out.points.response.x == out.points.excitation.x &&
                       out.points.response.y == out.points.excitation.y;
    if (layout.mass_loaded() && !point)
      prepared.at_response = model.receptance({out.points.response, out.points.response});
  } catch (const InputError& e) {
    if (!e.source().empty()) throw;
    throw InputError(frf.source, frf.label.empty() ? "positions" : frf.label + ", positions", e.problem());
  }
  // A receptance that is 0 whatever the parameters has no logarithm to fit.
  std::vector<double> file_values;
  for (const auto& p : layout.parameters) file_values.push_back(p.value);
  const double probe = 2.0 * std::numbers::pi * std::clamp(frf.frequency_hz[0], std::max(lo, 1e-3), hi);
  if (prepared.transfer->evaluate(file_values, probe, nullptr, {}) == 0.0) {
    std::ostringstream problem;
    problem << "the " << model.name() << " model's receptance from (" << out.points.excitation.x << ", "
            << out.points.excitation.y << ") m to (" << out.points.response.x << ", " << out.points.response.y
            << ") m is 0 with the model file's values: a simply supported belt edge (y = 0 or y = width) does not "
               "move, and a coupling of 0 transmits nothing; measure inside the belt, or start the coupling from a "
               "non-zero value";
    throw InputError(frf.source, frf.label.empty() ? "positions" : frf.label + ", positions", problem.str());
  }
  std::vector<Eigen::Index> lines;
  for (Eigen::Index k = 0; k < frf.size(); ++k)
    if (frf.frequency_hz[k] >= lo && frf.frequency_hz[k] <= hi) lines.push_back(k);
  if (lines.empty())
    throw InputError(frf.source, frf.label,
                     "no frequency overlap: the data spans " + hz_text(frf.frequency_hz[0]) + " to " +
                         hz_text(frf.frequency_hz[frf.size() - 1]) + " Hz, the band to fit is " + band_text);
  const auto n = static_cast<Eigen::Index>(lines.size());
  out.frequency_hz.resize(n);
  out.measured.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    out.frequency_hz[i] = frf.frequency_hz[lines[static_cast<std::size_t>(i)]];
    out.measured[i] = frf.mobility[lines[static_cast<std::size_t>(i)]];
  }
  out.weight = band_weights(out.frequency_hz);
  out.left_out = frf.size() - n;
  return prepared;
}

struct Line {
  std::unique_ptr<FrfPointResidual> residual;
  double weight = 0.0;
  std::size_t frf = 0;
  Eigen::Index index = 0;
};

// The weak prior of a continuation's early stages: r = x − x_start (unit Jacobian), so that a
// factor e in a log-scaled parameter costs ½.
class StartPrior : public ceres::CostFunction {
 public:
  explicit StartPrior(std::vector<double> start) : start_(std::move(start)) {
    set_num_residuals(static_cast<int>(start_.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(start_.size()));
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::size_t n = start_.size();
    for (std::size_t j = 0; j < n; ++j) residuals[j] = parameters[0][j] - start_[j];
    if (jacobians != nullptr && jacobians[0] != nullptr)
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) jacobians[0][i * n + j] = i == j ? 1.0 : 0.0;
    return true;
  }

 private:
  std::vector<double> start_;
};

// The Cauchy loss ρ(s) = a²·ln(1 + s/a²) and its slope ρ'(s) = 1/(1 + s/a²).
double cauchy_slope(double s, double scale) { return 1.0 / (1.0 + s / (scale * scale)); }

}  // namespace

CalibrationResult calibrate(const CalibrationModel& model, const std::vector<MeasuredFrf>& data,
                            const CalibrationSettings& settings) {
  if (data.empty()) throw InputError("--data", "", "no measured FRF given");
  if (!(settings.loss_scale > 0.0)) throw InputError("--loss-scale", "", "must be > 0");
  const FitLayout layout = make_layout(model, settings);
  const std::size_t unknowns = layout.unknowns();

  // The band to fit: the model's valid range within --frequency-range.
  const double model_max = model.highest_frequency_hz();
  const double lo = std::max(settings.min_frequency_hz, 0.0);
  const double hi = std::min(settings.max_frequency_hz, model_max);
  std::string band_text = hz_text(lo) + " to " + hz_text(hi) + " Hz (";
  band_text += std::isfinite(model_max) ? "the " + model.name() + " model's modal truncation reaches " +
                                              hz_text(model_max) + " Hz"
                                        : "the " + model.name() + " model has no upper limit";
  band_text += "; --frequency-range narrows it)";
  if (!(lo < hi)) throw InputError("--frequency-range", "", "leaves nothing to fit: the band is " + band_text);

  std::vector<PreparedFrf> frfs;
  for (const MeasuredFrf& frf : data) frfs.push_back(prepare(model, frf, layout, lo, hi, band_text));

  // Frequency continuation: the stages' tops, doubling from the first to the band's top.
  std::vector<double> stage_tops;
  const double first_stage = settings.first_stage_hz < 0.0 ? model.first_stage_hz() : settings.first_stage_hz;
  if (!std::isfinite(first_stage)) throw InputError("--first-stage", "", "must be a frequency in Hz (0: none)");
  // A stage adds a band worth fitting on its own only when the next top is well above it.
  constexpr double least_step = 1.5;
  for (double top = first_stage; top > lo && top * least_step < hi; top *= 2.0) stage_tops.push_back(top);
  stage_tops.push_back(hi);

  std::vector<Line> lines;
  for (std::size_t f = 0; f < frfs.size(); ++f) {
    const PreparedFrf& p = frfs[f];
    for (Eigen::Index k = 0; k < p.out.frequency_hz.size(); ++k) {
      Line line;
      line.residual = std::make_unique<FrfPointResidual>(layout, *p.transfer, p.at_response.get(),
                                                         p.out.frequency_hz[k], p.out.measured[k]);
      line.weight = p.out.weight[k];
      line.frf = f;
      line.index = k;
      lines.push_back(std::move(line));
    }
  }

  std::vector<double> lower, upper;
  unknown_bounds(layout, lower, upper);
  const std::vector<std::vector<double>> starts = starting_points(layout, settings);

  CalibrationResult result;
  result.model = model.name();
  std::vector<double> best;
  double best_cost = std::numeric_limits<double>::infinity();
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.loss_function_ownership = ceres::TAKE_OWNERSHIP;

  // Reports every iteration to the caller's progress function.
  class Progress : public ceres::IterationCallback {
   public:
    Progress(const CalibrationSettings& settings, int start) : settings_(settings), start_(start) {}
    // An exception from the progress function (Interrupted, on Ctrl-C) must not cross Ceres:
    // the solve is aborted and the exception rethrown after it (rethrow_failure).
    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
      try {
        if (settings_.progress)
          settings_.progress(start_, static_cast<int>(std::max(1, settings_.starts)), done + summary.iteration);
      } catch (...) {
        failure = std::current_exception();
        return ceres::SOLVER_ABORT;
      }
      return ceres::SOLVER_CONTINUE;
    }
    void rethrow_failure() const {
      if (failure) std::rethrow_exception(failure);
    }
    int done = 0;  // iterations of the earlier stages: the count runs on through the stages
    std::exception_ptr failure;

   private:
    const CalibrationSettings& settings_;
    int start_;
  };

  for (std::size_t s = 0; s < starts.size(); ++s) {
    std::vector<double> x = starts[s];
    StartOutcome outcome;
    outcome.start = starts[s];
    Progress progress(settings, static_cast<int>(s));
    for (std::size_t stage = 0; stage < stage_tops.size(); ++stage) {
      const bool last = stage + 1 == stage_tops.size();
      ceres::Problem problem(problem_options);
      problem.AddParameterBlock(x.data(), static_cast<int>(unknowns));
      std::size_t in_band = 0;
      for (const Line& line : lines) {
        if (!last && frfs[line.frf].out.frequency_hz[line.index] > stage_tops[stage]) continue;
        auto* loss =
            new ceres::ScaledLoss(new ceres::CauchyLoss(settings.loss_scale), line.weight, ceres::TAKE_OWNERSHIP);
        problem.AddResidualBlock(line.residual.get(), loss, x.data());
        ++in_band;
      }
      // A stage needs more lines than unknowns to say anything of its own.
      if (!last && 2 * in_band <= unknowns) continue;
      StartPrior prior(x);  // the problem does not own its cost functions
      if (!last) problem.AddResidualBlock(&prior, nullptr, x.data());
      for (std::size_t j = 0; j < unknowns; ++j) {
        problem.SetParameterLowerBound(x.data(), static_cast<int>(j), lower[j]);
        problem.SetParameterUpperBound(x.data(), static_cast<int>(j), upper[j]);
      }
      ceres::Solver::Options options;
      options.minimizer_type = ceres::TRUST_REGION;
      options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
      options.linear_solver_type = ceres::DENSE_QR;
      options.max_num_iterations = settings.max_iterations;
      // The stages before the last need only bring the start into the last one's basin.
      options.function_tolerance = last ? model.function_tolerance() : std::max(model.function_tolerance(), 1e-6);
      options.gradient_tolerance = 1e-14;
      options.parameter_tolerance = 1e-12;
      options.num_threads = 1;  // deterministic, and the machine is shared
      options.logging_type = ceres::SILENT;
      options.minimizer_progress_to_stdout = false;
      options.callbacks.push_back(&progress);
      ceres::Solver::Summary summary;
      ceres::Solve(options, &problem, &summary);
      progress.rethrow_failure();
      outcome.iterations += static_cast<int>(summary.num_successful_steps + summary.num_unsuccessful_steps);
      progress.done += static_cast<int>(summary.iterations.size());
      if (!last) continue;
      outcome.cost = summary.termination_type == ceres::FAILURE ? std::numeric_limits<double>::infinity()
                                                                 : summary.final_cost;
      outcome.termination = ceres::TerminationTypeToString(summary.termination_type);
    }
    if (outcome.cost < best_cost) {
      best_cost = outcome.cost;
      best = x;
      result.best_start = static_cast<int>(s);
      result.iterations = outcome.iterations;
    }
    result.starts.push_back(std::move(outcome));
  }
  if (best.empty())
    throw std::runtime_error("calibrate: no start reached a finite cost (the model could not be evaluated)");
  result.cost = best_cost;
  result.stage_tops_hz = stage_tops;

  // Residuals and Jacobians at the optimum, without loss or weight.
  std::vector<Eigen::Vector2d> r(lines.size());
  std::vector<Eigen::MatrixXd> J(lines.size(), Eigen::MatrixXd(2, static_cast<Eigen::Index>(unknowns)));
  {
    const double* parameters[] = {best.data()};
    std::vector<double> jac(2 * unknowns);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      double* jacobians[] = {jac.data()};
      if (!lines[i].residual->Evaluate(parameters, r[i].data(), jacobians))
        throw std::runtime_error("calibrate: the model cannot be evaluated at the optimum");
      for (std::size_t j = 0; j < unknowns; ++j) {
        J[i](0, static_cast<Eigen::Index>(j)) = jac[j];
        J[i](1, static_cast<Eigen::Index>(j)) = jac[unknowns + j];
      }
    }
  }
  // Effective weights v = w·ρ'(s) and the residual variance from the lines the loss kept.
  std::vector<double> v(lines.size());
  double kept_squares = 0.0, kept_components = 0.0, sum_log_mag = 0.0, sum_phase = 0.0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double s2 = r[i].squaredNorm();
    const double slope = cauchy_slope(s2, settings.loss_scale);
    v[i] = lines[i].weight * slope;
    kept_squares += slope * s2;
    kept_components += 2.0 * slope;
    sum_log_mag += r[i][0] * r[i][0];
    sum_phase += r[i][1] * r[i][1];
  }
  const double dof = kept_components - static_cast<double>(unknowns);
  const double variance = dof > 0.0 ? kept_squares / dof : kept_squares;
  result.residual_sigma = std::sqrt(variance);
  result.lines = lines.size();
  result.rms_log_magnitude = std::sqrt(sum_log_mag / static_cast<double>(lines.size()));
  result.rms_phase = std::sqrt(sum_phase / static_cast<double>(lines.size()));

  // C = (Jᵀ V J)⁻¹ from Ceres' covariance of the weighted problem.
  const auto n = static_cast<Eigen::Index>(unknowns);
  Eigen::MatrixXd C(n, n);
  {
    std::vector<double> x = best;
    ceres::Problem weighted(problem_options);
    weighted.AddParameterBlock(x.data(), static_cast<int>(unknowns));
    for (std::size_t i = 0; i < lines.size(); ++i)
      weighted.AddResidualBlock(lines[i].residual.get(), new ceres::ScaledLoss(nullptr, v[i], ceres::TAKE_OWNERSHIP),
                                x.data());
    // Rank: Ceres' own test for DENSE_SVD (σ_min/σ_max of the weighted Jacobian below
    // √1e-14), taken here so that Ceres does not log an error for data that leave a direction
    // undetermined; the covariance is then its pseudo-inverse.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t i = 0; i < lines.size(); ++i) A += v[i] * (J[i].transpose() * J[i]);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
    constexpr double min_reciprocal_condition = 1e-14;
    result.full_rank = eigenvalues.minCoeff() > min_reciprocal_condition * eigenvalues.maxCoeff();
    result.singular_values = eigenvalues.reverse().cwiseMax(0.0).cwiseSqrt();  // A = (√V J)ᵀ(√V J)
    ceres::Covariance::Options options;
    options.algorithm_type = ceres::DENSE_SVD;
    options.min_reciprocal_condition_number = min_reciprocal_condition;
    options.null_space_rank = -1;  // drop the directions below the threshold (none when of full rank)
    options.num_threads = 1;
    const std::vector<std::pair<const double*, const double*>> blocks = {{x.data(), x.data()}};
    ceres::Covariance covariance(options);
    if (covariance.Compute(blocks, &weighted))
      covariance.GetCovarianceBlock(x.data(), x.data(), C.data());
    else
      C.setConstant(std::numeric_limits<double>::quiet_NaN());
    C.transposeInPlace();  // row-major from Ceres; symmetric anyway
  }
  // The sandwich C·(Jᵀ V² J)·C·σ²: the weights are not inverse variances, so the plain
  // σ²·C would misstate the spread.
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t i = 0; i < lines.size(); ++i) B += v[i] * v[i] * (J[i].transpose() * J[i]);
  result.covariance = variance * C * B * C;
  result.correlation = Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b)
      if (a != b)
        result.correlation(a, b) =
            result.covariance(a, b) / std::sqrt(result.covariance(a, a) * result.covariance(b, b));

  // The fitted values and their standard errors.
  std::vector<double> values;
  double mass = 0.0;
  layout.values(best.data(), values, mass);
  result.values = values;
  result.transducer_mass = mass;
  for (const auto& p : layout.parameters) result.parameter_names.push_back(p.name);
  for (std::size_t j = 0; j < unknowns; ++j) {
    const bool is_mass = j == layout.free.size();
    const FitParameter p = is_mass ? log_parameter("transducer_mass", "kg", layout.transducer_mass)
                                   : layout.parameters[layout.free[j]];
    FittedParameter f;
    f.name = p.name;
    f.unit = p.unit;
    f.initial = p.value;
    f.value = is_mass ? mass : values[layout.free[j]];
    f.lower = p.lower;
    f.upper = p.upper;
    f.log_scale = p.log_scale;
    const auto jj = static_cast<Eigen::Index>(j);
    f.log_std_error = std::sqrt(std::max(0.0, result.covariance(jj, jj)));
    f.std_error = f.log_std_error * layout.value_per_unknown(j, values, mass);
    f.at_bound = std::abs(best[j] - lower[j]) <= 1e-6 * std::max(1.0, std::abs(lower[j])) ||
                 std::abs(best[j] - upper[j]) <= 1e-6 * std::max(1.0, std::abs(upper[j]));
    result.fitted.push_back(f);
  }

  // Warnings: what the data do not determine.
  if (!result.full_rank)
    result.warnings.push_back(
        "the covariance is rank-deficient: the data do not determine every free parameter (standard errors are from "
        "the pseudo-inverse and understate the uncertainty); fix some parameters or add FRFs");
  for (std::size_t j = 0; j < unknowns; ++j) {
    const FittedParameter& f = result.fitted[j];
    std::ostringstream w;
    if (!std::isfinite(f.log_std_error) || (f.log_scale && f.log_std_error > 1.0)) {
      w << f.name << " is not identifiable from the data: its relative standard error is "
        << (std::isfinite(f.log_std_error) ? std::to_string(static_cast<int>(std::lround(100.0 * f.log_std_error)))
                                           : std::string("undefined"))
        << " %";
      result.warnings.push_back(w.str());
    }
    if (f.at_bound) {
      std::ostringstream b;
      b << f.name << " ended at its bound [" << f.lower << ", " << f.upper
        << "]: the data pull it beyond three decades of the model file's value";
      result.warnings.push_back(b.str());
    }
    for (std::size_t k = j + 1; k < unknowns; ++k) {
      const double rho = result.correlation(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k));
      if (std::abs(rho) > 0.99) {
        std::ostringstream c;
        c.precision(4);
        c << f.name << " and " << result.fitted[k].name << " are correlated (rho = " << rho
          << "): the data determine a combination of them, not each one";
        result.warnings.push_back(c.str());
      }
    }
  }

  // The fitted mobilities.
  for (std::size_t i = 0; i < lines.size(); ++i) {
    FittedFrf& out = frfs[lines[i].frf].out;
    if (out.fitted.size() != out.frequency_hz.size()) out.fitted.resize(out.frequency_hz.size());
    out.fitted[lines[i].index] = lines[i].residual->model_mobility(best.data());
  }
  result.fit_min_hz = lo;
  result.fit_max_hz = hi;
  for (PreparedFrf& p : frfs) result.frfs.push_back(std::move(p.out));
  return result;
}

}  // namespace rollnoise
