// _rollnoise: the extension under the Python package rollnoise (python/rollnoise/__init__.py,
// which holds the documented functions). It calls the same library functions as the command
// line's verbs (src/simulation: run_case, run_road, analyse_recording; src/greens,
// src/calibrate, src/study), with these differences only:
//  - every run goes on a worker thread while the calling thread waits with the GIL released,
//    waking every 50 ms to pass on the progress (a callback called in the calling thread) and to
//    look for a pending KeyboardInterrupt, on which it stops the run (core/cancellation.hpp,
//    RunCancellation: the staging folder is removed, nothing is half-written) and raises it;
//  - InputError becomes rollnoise.InputError (a ValueError) and OutputError rollnoise.OutputError
//    (an OSError), with the command line's message.
#include <array>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <toml++/toml.h>

#include "audio/wav_file.hpp"
#include "core/cache_folder.hpp"
#include "core/cancellation.hpp"
#include "core/case_file.hpp"
#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "core/output_directory.hpp"
#include "core/progress.hpp"
#include "simulation/calibration_run.hpp"
#include "simulation/case_run.hpp"
#include "simulation/greens_run.hpp"
#include "simulation/recording_analysis.hpp"
#include "simulation/road_run.hpp"
#include "study/mpi_session.hpp"
#include "study/study_run.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;
using namespace rollnoise;

namespace {

// The progress a run reports from its worker thread, read by the waiting thread.
class LatestProgress final : public ProgressSink {
 public:
  void report(const std::string& stage, std::size_t done, std::size_t total) noexcept override {
    try {
      const std::lock_guard lock(mutex_);
      stage_ = stage;
      done_ = done;
      total_ = total;
      fresh_ = true;
    } catch (...) {
      // a string that cannot be copied: this report is skipped
    }
  }
  // The report since the last take, if any.
  bool take(std::string& stage, std::size_t& done, std::size_t& total) {
    const std::lock_guard lock(mutex_);
    if (!fresh_) return false;
    fresh_ = false;
    stage = stage_;
    done = done_;
    total = total_;
    return true;
  }

 private:
  std::mutex mutex_;
  std::string stage_;
  std::size_t done_ = 0;
  std::size_t total_ = 0;
  bool fresh_ = false;
};

// Runs `work(sink)` on a worker thread with the GIL released; see the file's comment. `work`
// must not touch Python objects. Exceptions of the work are rethrown here (and translated by
// the module's translators); a KeyboardInterrupt or an exception of the callback stops the run
// and is raised once the worker has ended.
template <class Work>
auto run_released(const py::object& progress, Work&& work) -> decltype(work(static_cast<ProgressSink*>(nullptr))) {
  using Result = decltype(work(static_cast<ProgressSink*>(nullptr)));
  LatestProgress sink;
  ProgressSink* sink_pointer = progress.is_none() ? nullptr : &sink;
  const RunCancellation cancellation;
  std::optional<Result> result;
  std::exception_ptr failure;
  std::mutex mutex;
  std::condition_variable ended;
  bool done = false;
  std::thread worker([&] {
    try {
      result.emplace(work(sink_pointer));
    } catch (...) {
      failure = std::current_exception();
    }
    const std::lock_guard lock(mutex);
    done = true;
    ended.notify_all();
  });
  const auto wait = [&](std::chrono::milliseconds timeout) {
    const py::gil_scoped_release release;
    std::unique_lock lock(mutex);
    if (timeout.count() > 0) {
      ended.wait_for(lock, timeout, [&] { return done; });
    } else {
      ended.wait(lock, [&] { return done; });
    }
    return done;
  };
  const auto pass_on_progress = [&] {
    std::string stage;
    std::size_t steps = 0;
    std::size_t total = 0;
    if (sink_pointer && sink.take(stage, steps, total)) progress(stage, steps, total);
  };
  std::optional<py::error_already_set> raised;
  while (!wait(std::chrono::milliseconds(50))) {
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      pass_on_progress();
    } catch (py::error_already_set& error) {
      raised.emplace(std::move(error));
      cancellation.cancel(SIGINT);
      wait(std::chrono::milliseconds(0));
      break;
    } catch (...) {
      cancellation.cancel(SIGINT);
      wait(std::chrono::milliseconds(0));
      worker.join();
      throw;
    }
  }
  worker.join();
  if (raised) throw std::move(*raised);
  if (failure) std::rethrow_exception(failure);
  pass_on_progress();
  return std::move(*result);
}

// run_released for a verb that writes its outputs only when asked: `compute(sink)`, then
// `write(out, result)` when `out` is given, both on the worker thread (a write is part of the
// run: Ctrl-C stops it too).
template <class Compute, class Write>
auto run_then_write(const py::object& progress, const std::string& out, Compute&& compute, Write&& write) {
  return run_released(progress, [&](ProgressSink* sink) {
    auto made = compute(sink);
    if (!out.empty()) write(out, made);
    return made;
  });
}

// A Python value as a TOML node (a dict given for a case or a road): dict → table, list/tuple →
// array, bool, int, float, str. Anything else is an InputError naming the key.
std::unique_ptr<toml::node> to_toml(const py::handle& value, const std::string& where, const std::string& source);

toml::table to_toml_table(const py::dict& dict, const std::string& where, const std::string& source) {
  toml::table table;
  for (const auto& [key, value] : dict) {
    if (!py::isinstance<py::str>(key)) throw InputError(source, where, "keys must be strings");
    const std::string name = key.cast<std::string>();
    const std::string path = where.empty() ? name : where + "." + name;
    std::unique_ptr<toml::node> node = to_toml(value, path, source);
    if (!node) continue;  // None: the key is left out
    table.insert_or_assign(name, std::move(*node));
  }
  return table;
}

std::unique_ptr<toml::node> to_toml(const py::handle& value, const std::string& where, const std::string& source) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return std::make_unique<toml::value<bool>>(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return std::make_unique<toml::value<std::int64_t>>(value.cast<std::int64_t>());
  if (py::isinstance<py::float_>(value)) return std::make_unique<toml::value<double>>(value.cast<double>());
  if (py::isinstance<py::str>(value)) return std::make_unique<toml::value<std::string>>(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) return std::make_unique<toml::table>(to_toml_table(value.cast<py::dict>(), where, source));
  // numpy scalars and other numbers
  const py::module_ numbers = py::module_::import("numbers");
  if (py::isinstance(value, numbers.attr("Integral")))
    return std::make_unique<toml::value<std::int64_t>>(
        py::int_(py::reinterpret_borrow<py::object>(value)).cast<std::int64_t>());
  if (py::isinstance(value, numbers.attr("Real")))
    return std::make_unique<toml::value<double>>(py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
  if (py::isinstance<py::sequence>(value) || py::isinstance<py::array>(value)) {
    auto array = std::make_unique<toml::array>();
    std::size_t i = 0;
    for (const py::handle& item : py::iter(value)) {
      std::unique_ptr<toml::node> node = to_toml(item, where + "[" + std::to_string(i++) + "]", source);
      if (!node) throw InputError(source, where, "a list cannot hold None");
      array->push_back(std::move(*node));
    }
    return array;
  }
  throw InputError(source, where,
                   "cannot be written in TOML: " + py::str(py::type::of(value).attr("__name__")).cast<std::string>() +
                       " (allowed: dict, list, bool, int, float, str)");
}

// The cache folder of a run: True the default one, False none, a path that folder.
std::optional<fs::path> cache_of(const py::object& cache) {
  if (py::isinstance<py::bool_>(cache)) {
    if (!cache.cast<bool>()) return std::nullopt;
    return usable_cache_folder({}, false);
  }
  if (cache.is_none()) return std::nullopt;
  return usable_cache_folder(py::str(cache).cast<std::string>(), false);
}

// A case from its three forms: a path, TOML text, or a dict (already split by the package).
CaseFile load_case(const std::string& kind, const py::object& value, const std::string& name,
                   const std::vector<std::string>& overrides) {
  if (kind == "path") return CaseFile::load(value.cast<std::string>(), overrides);
  if (kind == "text") return CaseFile::from_table(name, parse_toml_text(value.cast<std::string>(), name), overrides);
  return CaseFile::from_table(name, to_toml_table(value.cast<py::dict>(), "", name), overrides);
}

// The TOML of a road or model given as text or a dict (std::nullopt for a path), named `name`.
std::optional<toml::table> toml_of(const std::string& kind, const py::object& value, const std::string& name) {
  try {
    if (kind == "text") return parse_toml_text(value.cast<std::string>(), name);
    if (kind == "dict") return to_toml_table(value.cast<py::dict>(), "", name);
  } catch (const InputError& error) {
    throw error.with_source(name);
  }
  return std::nullopt;
}

py::dict py_simulate(const std::string& kind, const py::object& value, const std::string& name,
                     const std::vector<std::string>& overrides, const std::string& out, const py::object& cache,
                     bool force, const py::object& progress) {
  const CaseFile file = [&] {
    try {
      return load_case(kind, value, name, overrides);
    } catch (const InputError& error) {
      throw error.with_source(name);
    }
  }();
  CaseRunOptions options;
  options.progress = false;  // the caller shows progress its own way
  options.cache = cache_of(cache);
  options.force = force;
  const CaseResult result = run_released(progress, [&](ProgressSink* sink) {
    CaseRunOptions run = options;
    run.progress_sink = sink;
    return run_case(file, out, run);
  });
  py::dict answer;
  answer["summary"] = result.summary.dump();
  answer["out"] = result.out.string();
  answer["written"] = result.written;
  return answer;
}

py::array_t<double> matrix_of(const std::vector<std::vector<double>>& rows) {
  const std::size_t n = rows.size();
  const std::size_t m = rows.empty() ? 0 : rows.front().size();
  py::array_t<double> a({n, m});
  auto view = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) view(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = rows[i][j];
  return a;
}

py::dict road_answer(const RoadRun& road) {
  py::dict answer;
  answer["x"] = py::array_t<double>(static_cast<py::ssize_t>(road.profile.x.size()), road.profile.x.data());
  answer["z"] = matrix_of(road.profile.z_lines);
  answer["y"] = py::array_t<double>(static_cast<py::ssize_t>(road.profile.y.size()), road.profile.y.data());
  std::vector<double> wavelength;
  std::vector<double> level;
  for (const TextureBand& b : road.analysis.texture) {
    wavelength.push_back(b.nominal_wavelength_m);
    level.push_back(b.level_db);
  }
  answer["wavelength_m"] = py::array_t<double>(static_cast<py::ssize_t>(wavelength.size()), wavelength.data());
  answer["Ltx_dB"] = py::array_t<double>(static_cast<py::ssize_t>(level.size()), level.data());
  std::vector<double> target_wavelength;
  std::vector<double> target_level;
  for (const auto& [w, l] : road.target) {
    target_wavelength.push_back(w);
    target_level.push_back(l);
  }
  answer["target_wavelength_m"] =
      py::array_t<double>(static_cast<py::ssize_t>(target_wavelength.size()), target_wavelength.data());
  answer["target_Ltx_dB"] = py::array_t<double>(static_cast<py::ssize_t>(target_level.size()), target_level.data());
  // An absorbing surface's bands (absorption.csv) and, when asked, the ground effect
  // (ground_effect.csv); empty arrays otherwise.
  std::vector<double> band, alpha, z_re, z_im;
  for (const AbsorptionBand& b : road.absorption_bands) {
    band.push_back(b.band_hz);
    alpha.push_back(b.alpha);
    z_re.push_back(b.impedance.real());
    z_im.push_back(b.impedance.imag());
  }
  const auto array = [](const std::vector<double>& v) { return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data()); };
  answer["absorption_band_hz"] = array(band);
  answer["alpha"] = array(alpha);
  answer["z_re"] = array(z_re);
  answer["z_im"] = array(z_im);
  std::vector<double> ground_band, delta, delta_band;
  for (const GroundEffectBand& b : road.ground_effect) {
    ground_band.push_back(b.band_hz);
    delta.push_back(b.delta_db);
    delta_band.push_back(b.delta_band_db);
  }
  answer["ground_band_hz"] = array(ground_band);
  answer["delta_dB"] = array(delta);
  answer["delta_band_dB"] = array(delta_band);
  answer["summary"] = road.summary.dump();
  return answer;
}

py::dict py_road(const std::string& kind, const py::object& value, const std::string& name,
              const std::vector<std::string>& overrides, double length, std::optional<double> spacing, int lines,
              double width, bool force, const std::string& out, const py::object& progress,
              const std::optional<std::array<double, 3>>& ground_effect) {
  RoadRunOptions options;
  if (ground_effect) {
    options.ground_effect = GroundEffectGeometry{(*ground_effect)[0], (*ground_effect)[1], (*ground_effect)[2]};
    options.ground_effect_source = name;
    options.ground_effect_key = "ground_effect";
  }
  options.input = kind == "path" ? value.cast<std::string>() : name;
  options.toml = toml_of(kind, value, name);
  options.overrides = overrides;
  options.length = length;
  if (spacing) {
    options.spacing = *spacing;
    options.spacing_given = true;
  }
  options.lines = lines;
  options.width = width;
  options.force = force;
  const RoadRun result = run_then_write(
      progress, out,
      [&](ProgressSink* sink) {
        RoadRunOptions run = options;
        run.progress_sink = sink;
        return run_road(run, out);
      },
      write_road_outputs);
  return road_answer(result);
}

py::dict py_road_heights(const py::array_t<double, py::array::c_style | py::array::forcecast>& z, double spacing,
                      const std::vector<double>& y, const std::string& name, const std::string& out) {
  if (z.ndim() != 1 && z.ndim() != 2)
    throw InputError(name, "", "heights must be an array of one line (samples) or of lines × samples");
  const py::ssize_t lines = z.ndim() == 1 ? 1 : z.shape(0);
  const py::ssize_t samples = z.ndim() == 1 ? z.shape(0) : z.shape(1);
  std::vector<std::vector<double>> z_lines(static_cast<std::size_t>(lines), std::vector<double>(static_cast<std::size_t>(samples)));
  const double* data = z.data();
  for (py::ssize_t j = 0; j < lines; ++j)
    for (py::ssize_t i = 0; i < samples; ++i)
      z_lines[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] = data[j * samples + i];
  const RoadRun result = run_then_write(
      py::none(), out, [&](ProgressSink*) { return run_road_heights(std::move(z_lines), spacing, y, name); },
      write_road_outputs);
  return road_answer(result);
}

py::dict analysis_answer(const RecordingAnalysis& analysis) {
  py::dict spectra;
  for (std::size_t i = 0; i < analysis.signals.size(); ++i) {
    const BandSpectrum& s = analysis.report.spectra[i];
    py::dict one;
    one["band_hz"] = py::array_t<double>(static_cast<py::ssize_t>(s.nominal_hz.size()), s.nominal_hz.data());
    one["Lp_dB"] = py::array_t<double>(static_cast<py::ssize_t>(s.lp_db.size()), s.lp_db.data());
    one["LpA_dB"] = py::array_t<double>(static_cast<py::ssize_t>(s.lpa_db.size()), s.lpa_db.data());
    spectra[py::str(analysis.signals[i].name)] = one;
  }
  py::dict answer;
  answer["spectrum"] = spectra;
  answer["summary"] = analysis.summary.dump();
  return answer;
}

py::dict py_analyse_file(const std::string& path, double full_scale, const std::string& out) {
  const RecordingAnalysis result = run_then_write(
      py::none(), out, [&](ProgressSink*) { return analyse_recording(path, full_scale); }, write_recording_analysis);
  return analysis_answer(result);
}

py::dict py_analyse_signals(const std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>>& signals,
                         const std::vector<std::string>& names, double sample_rate, const std::string& input,
                         const std::string& out) {
  std::vector<ReceiverSignal> receivers;
  for (std::size_t i = 0; i < signals.size(); ++i) {
    const auto& s = signals[i];
    if (s.ndim() != 1) throw InputError(input, names[i], "a signal must be one-dimensional (samples)");
    ReceiverSignal r;
    r.name = names[i];
    r.pressure = Eigen::Map<const Eigen::VectorXd>(s.data(), s.shape(0));
    r.sample_rate = sample_rate;
    receivers.push_back(std::move(r));
  }
  const RecordingAnalysis result = run_then_write(
      py::none(), out, [&](ProgressSink*) { return analyse_signals(std::move(receivers), input); },
      write_recording_analysis);
  return analysis_answer(result);
}

py::array_t<double> vector_of(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

// An Eigen matrix (column-major) as a C-ordered numpy array.
template <class Matrix>
py::array_t<typename Matrix::Scalar> matrix_array(const Matrix& m) {
  py::array_t<typename Matrix::Scalar> a({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  auto view = a.template mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) view(i, j) = m(i, j);
  return a;
}

py::dict py_greens(const std::string& kind, const py::object& value, const std::string& name,
                   const std::vector<double>& frequencies, const std::vector<double>& distances, const py::object& cache,
                   bool force, const std::string& out) {
  GreensRunOptions options;
  options.model = kind == "path" ? value.cast<std::string>() : name;
  options.toml = toml_of(kind, value, name);
  options.frequencies = frequencies;
  options.distances = distances;
  options.cache = cache_of(cache);
  options.force = force;
  const GreensRun result = run_then_write(
      py::none(), out, [&](ProgressSink*) { return run_greens(options, out); }, write_greens_outputs);
  py::dict answer;
  answer["frequency_hz"] = vector_of(result.frequencies);
  answer["distance_m"] = vector_of(result.distances);
  answer["receptance"] = matrix_array(result.receptance);
  answer["mobility"] = matrix_array(result.mobility);
  answer["time"] = py::array_t<double>(result.time.size(), result.time.data());
  answer["green_distance_m"] = vector_of(result.around);
  answer["green"] = matrix_array(result.green);
  answer["summary"] = result.summary.dump();
  return answer;
}

py::dict py_calibrate(const std::string& model, const std::vector<std::string>& data, const std::vector<std::string>& fit,
                      const std::string& data_type, bool data_type_given, const std::vector<std::string>& response,
                      const std::vector<std::string>& excitation, const std::vector<std::string>& nodes,
                      double transducer_mass, const std::string& frequency_range, int starts, std::uint64_t seed,
                      double loss_scale, double first_stage, bool force, const std::string& out,
                      const py::object& progress) {
  CalibrationRunOptions options;
  options.model = model;
  options.data = data;
  options.fit = fit;
  options.data_type = data_type;
  options.data_type_given = data_type_given;
  options.response = response;
  options.excitation = excitation;
  options.nodes = nodes;
  options.transducer_mass = transducer_mass;
  options.frequency_range = frequency_range;
  options.starts = starts;
  options.seed = seed;
  options.loss_scale = loss_scale;
  options.first_stage = first_stage;
  options.force = force;
  options.progress = false;
  const CalibrationRun result = run_then_write(
      progress, out,
      [&](ProgressSink* sink) {
        CalibrationRunOptions run = options;
        run.progress_sink = sink;
        return run_calibration(run, out);
      },
      write_calibration_outputs);
  py::list frfs;
  for (const FittedFrf& f : result.result.frfs) {
    py::dict one;
    one["name"] = f.name;
    one["frequency_hz"] = py::array_t<double>(f.frequency_hz.size(), f.frequency_hz.data());
    one["measured"] = py::array_t<std::complex<double>>(f.measured.size(), f.measured.data());
    one["fitted"] = py::array_t<std::complex<double>>(f.fitted.size(), f.fitted.data());
    one["weight"] = py::array_t<double>(f.weight.size(), f.weight.data());
    frfs.append(one);
  }
  py::dict answer;
  answer["frfs"] = frfs;
  answer["notes"] = result.notes;
  answer["calibrated"] = result.calibrated;
  answer["report"] = result.report.dump();
  return answer;
}

py::dict py_study(const std::string& path, const std::string& out, int threads, bool fail_fast, bool restart, bool yes,
               const py::object& cache, const py::object& progress) {
  StudyRunOptions options;
  options.out = out;
  options.threads = threads;
  options.fail_fast = fail_fast;
  options.progress = false;
  options.cache = cache_of(cache);
  const StudyRun result = run_released(progress, [&](ProgressSink* sink) {
    MpiSession mpi;  // one rank: the module is not run under mpirun
    StudyRunOptions run = options;
    run.progress_sink = sink;
    return run_study(path, run, restart, yes, mpi);
  });
  py::dict answer;
  answer["out"] = result.out.string();
  answer["summary"] = result.summary.dump();
  return answer;
}

// A dataset of an HDF5 file rollnoise wrote (contact.h5, greens.h5), as a numpy array.
py::array_t<double> read_h5(const std::string& path, const std::string& dataset) {
  Hdf5Array array;
  {
    const py::gil_scoped_release release;
    const Hdf5Reader reader(path);
    array = reader.read_numbers(dataset, 4, std::size_t{1} << 34);
  }
  std::vector<py::ssize_t> shape(array.dims.begin(), array.dims.end());
  py::array_t<double> a(shape);
  std::copy(array.values.begin(), array.values.end(), a.mutable_data());
  return a;
}

std::optional<double> h5_number_attribute(const std::string& path, const std::string& object, const std::string& name) {
  const Hdf5Reader reader(path);
  return reader.number_attribute(object, name);
}

py::tuple read_wav_file(const std::string& path) {
  const WavData wav = read_wav(path);
  py::list channels;
  for (const Eigen::VectorXd& c : wav.channels) channels.append(py::array_t<double>(c.size(), c.data()));
  return py::make_tuple(channels, wav.sample_rate, wav.full_scale_pa ? py::cast(*wav.full_scale_pa) : py::none());
}

bool h5_exists(const std::string& path, const std::string& object) {
  const Hdf5Reader reader(path);
  return reader.exists(object);
}

}  // namespace

PYBIND11_MODULE(_rollnoise, m) {
  m.doc() = "The compiled part of the rollnoise package; use the functions of `rollnoise`.";
  m.attr("__version__") = ROLLNOISE_VERSION;

  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      error.attr("source") = e.source();
      error.attr("key") = e.key();
      error.attr("problem") = e.problem();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const OutputError& e) {
      PyErr_SetString(output_error.ptr(), e.what());
    } catch (const Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });

  m.def("simulate", &py_simulate, py::arg("kind"), py::arg("value"), py::arg("name"), py::arg("overrides"),
        py::arg("out"), py::arg("cache"), py::arg("force"), py::arg("progress"));
  m.def("road", &py_road, py::arg("kind"), py::arg("value"), py::arg("name"), py::arg("overrides"), py::arg("length"),
        py::arg("spacing"), py::arg("lines"), py::arg("width"), py::arg("force"), py::arg("out"), py::arg("progress"),
        py::arg("ground_effect"));
  m.def("road_heights", &py_road_heights, py::arg("z"), py::arg("spacing"), py::arg("y"), py::arg("name"), py::arg("out"));
  m.def("analyse_file", &py_analyse_file, py::arg("path"), py::arg("full_scale"), py::arg("out"));
  m.def("analyse_signals", &py_analyse_signals, py::arg("signals"), py::arg("names"), py::arg("sample_rate"),
        py::arg("input"), py::arg("out"));
  m.def("greens", &py_greens, py::arg("kind"), py::arg("value"), py::arg("name"), py::arg("frequencies"),
        py::arg("distances"), py::arg("cache"), py::arg("force"), py::arg("out"));
  m.def("calibrate", &py_calibrate, py::arg("model"), py::arg("data"), py::arg("fit"), py::arg("data_type"),
        py::arg("data_type_given"), py::arg("response"), py::arg("excitation"), py::arg("nodes"),
        py::arg("transducer_mass"), py::arg("frequency_range"), py::arg("starts"), py::arg("seed"), py::arg("loss_scale"),
        py::arg("first_stage"), py::arg("force"), py::arg("out"), py::arg("progress"));
  m.def("study", &py_study, py::arg("path"), py::arg("out"), py::arg("threads"), py::arg("fail_fast"), py::arg("restart"),
        py::arg("yes"), py::arg("cache"), py::arg("progress"));
  m.def("read_h5", &read_h5, py::arg("path"), py::arg("dataset"));
  m.def("h5_number_attribute", &h5_number_attribute, py::arg("path"), py::arg("object"), py::arg("name"));
  m.def("read_wav", &read_wav_file, py::arg("path"));
  m.def("h5_exists", &h5_exists, py::arg("path"), py::arg("object"));
}
