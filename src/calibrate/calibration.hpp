#pragma once
// Fits a model's parameters to measured FRFs (MODEL.md §6) with Ceres:
//
// - unknowns: the free parameters in log space (a coupling linearly), within physical bounds;
// - residuals: per frequency line, the complex log of model over measured mobility
//   (frf_residual.hpp), each line weighted by 1/(lines in its third-octave band) so every band
//   counts the same (band_weights.hpp), under a Cauchy loss: lines whose log residual is well
//   above `loss_scale` (outliers, a bad line near an anti-resonance) weigh less;
// - several starts: the model file's values, then seeded log-uniform draws within a factor of
//   ten of them (within bounds); the lowest cost wins. Same data and seed, same result;
// - frequency continuation (for models with many lightly damped modes, such as the two-layer
//   tyre): a start far from the truth sees the model's resonances between the measured ones,
//   where the phase of every line is off and the cost is a plateau with local minima (cycle
//   skipping). Each start then fits the lines up to a first top, where the modes are few and
//   the cost falls towards the truth, then up to twice that, and so on to the whole band, each
//   stage from the last one's result. The stages before the last add a weak prior
//   ½·Σ (x − x_start)² (a factor e in a parameter costs ½) that keeps the parameters their
//   band does not determine (a belt's bending at the lowest modes) from wandering off; the
//   last stage has none;
// - uncertainty: Ceres' covariance of the weighted problem at the optimum, scaled by the
//   residual variance found in the fit and corrected for the weights (the sandwich
//   C·(Jᵀ V² J)·C with C = (Jᵀ V J)⁻¹ and V the weights), so that the standard errors hold for
//   noise that is the same size on every line; correlations follow from it. Parameters the
//   data cannot tell apart get warnings.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "calibrate/calibration_model.hpp"
#include "calibrate/measured_frf.hpp"

namespace rollnoise {

struct CalibrationSettings {
  // Names of the free parameters: model-file keys, or "transducer_mass". Empty: the model's
  // default set.
  std::vector<std::string> free;
  double transducer_mass = 0.0;  // kg at every response point; the start value when fitted
  double min_frequency_hz = 0.0;  // the band to fit (within the model's valid range)
  double max_frequency_hz = std::numeric_limits<double>::infinity();
  int starts = 8;
  std::uint64_t seed = 1;
  double loss_scale = 0.25;  // Cauchy scale of the log residual (0.25 ≈ 2 dB or 14°)
  int max_iterations = 200;  // per start and stage
  // Frequency continuation: the top of the first stage in Hz; < 0: the model's choice
  // (CalibrationModel::first_stage_hz()); 0: none, the whole band at once.
  double first_stage_hz = -1.0;
  // Called after every iteration: (start, starts, iteration).
  std::function<void(int, int, int)> progress;
};

struct FittedParameter {
  std::string name;
  std::string unit;
  double initial = 0.0;  // from the model file (or --transducer-mass)
  double value = 0.0;
  double std_error = 0.0;      // of the value, from the covariance (σ_p ≈ p·σ_log p for log space)
  double log_std_error = 0.0;  // σ of log(p) (relative std error), or of p when not log-scaled
  double lower = 0.0;
  double upper = 0.0;
  bool log_scale = true;
  bool at_bound = false;
};

struct FittedFrf {
  std::string name;  // the file (and dataset)
  FrfPoints points;
  Eigen::VectorXd frequency_hz;  // the lines fitted
  Eigen::VectorXcd measured;     // mobility, m/(N·s)
  Eigen::VectorXcd fitted;       // the model's mobility with the fitted parameters (and mass loading)
  Eigen::VectorXd weight;        // band weight of each line
  Eigen::Index left_out = 0;     // lines outside the fitted band
};

struct StartOutcome {
  std::vector<double> start;  // unknowns at the start
  double cost = 0.0;          // of the last stage (the whole band)
  int iterations = 0;         // over all stages
  std::string termination;    // of the last stage
};

struct CalibrationResult {
  std::string model;
  std::vector<FittedParameter> fitted;  // the free parameters (transducer mass last if fitted)
  std::vector<std::string> parameter_names;  // all model parameters, in model order
  std::vector<double> values;                // all model parameters with the fitted values
  double transducer_mass = 0.0;
  Eigen::MatrixXd covariance;   // of the unknowns (log p, or p), in the order of `fitted`
  Eigen::MatrixXd correlation;  // from `covariance`
  bool full_rank = true;        // Ceres found the covariance well conditioned
  // The conditioning: singular values (largest first) of the weighted Jacobian at the optimum,
  // rows √(w·ρ') ∂r/∂x in the unknowns' units (log p): a direction with singular value s moves
  // the weighted residual by s per unit of log p, so its standard error is about σ/s.
  Eigen::VectorXd singular_values;
  double cost = 0.0;            // Ceres' final cost ½Σ w·ρ(|r|²) of the best start
  int iterations = 0;           // of the best start (all stages)
  std::vector<double> stage_tops_hz;  // the frequency continuation's stages (the last: the band's top)
  int best_start = 0;
  std::vector<StartOutcome> starts;
  double residual_sigma = 0.0;    // estimated σ of one residual component (log units)
  double rms_log_magnitude = 0.0;  // unweighted RMS of ln|Y_model/Y_measured|
  double rms_phase = 0.0;          // unweighted RMS of the phase difference, rad
  std::size_t lines = 0;           // frequency lines fitted
  double fit_min_hz = 0.0;         // the band fitted
  double fit_max_hz = 0.0;
  std::vector<FittedFrf> frfs;
  std::vector<std::string> warnings;
};

// Throws InputError for bad settings (source "--fit" and the like), FRFs without the
// positions a tyre model needs, and FRFs with no line in the band to fit.
CalibrationResult calibrate(const CalibrationModel& model, const std::vector<MeasuredFrf>& data,
                            const CalibrationSettings& settings);

}  // namespace rollnoise
