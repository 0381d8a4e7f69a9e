#pragma once
// The radiation stage of a rolling run (MODEL.md §5): the normal velocity of the tyre's surface
// over time in, the sound pressure over time at the receivers and the radiated sound power
// spectrum out.
//
// Method. The velocities are Fourier transformed (zero-padded, so the convolution with the
// receivers' responses is linear, not circular); at each frequency bin the equivalent-source
// model of the tyre over the rigid road (equivalent_sources.hpp, tyre_surface_mesh.hpp) maps
// them to pressures and power. Solving that model costs 0.2–5 s per frequency, so it is solved
// at anchor frequencies, in parallel, and interpolated between them:
//  - receiver pressures through TransferTable (the propagation delay taken out, so the signals
//    come out in retarded time: sample n is the sound the tyre emitted at step n);
//  - sound power as W = ½ qᴴSq (EquivalentSources::power_matrix) for the bin's own velocities,
//    with the radiation operator interpolated linearly between the two anchors around the bin:
//    each anchor's solve is applied to every bin within one anchor spacing of it, weighted by
//    the hat function. The power's bins are those of the record tapered at its ends
//    (power_taper.hpp), the pressures' those of the record as it is: the run's start and the
//    record's cut ends must not count in the power, which is quadratic in the velocities.
// The steady part of the velocities (the mean of each point) carries no sound and is removed.
// Below the lowest anchor and above the highest, nothing is radiated.
//
// Meshes per band. The mesh of the settings serves the anchors up to f₁ = c/(n·h), h its uniform
// tread spacing 2πR/Na and n = points_per_wavelength (4: 4.1 kHz for the default 96 around).
// Above, an anchor takes the same mesh with every tread cell split in 2 (4, …) along the tread
// (TyreSurfaceMeshSpec::tread_split), serving up to 2f₁ (4f₁, …), and as many sidewall rings as
// give n per wavelength at the top of its band (at least the base's). The solve costs
// ∝ rows·columns², about the cube of the point count, so the few upper anchors on the finer mesh
// cost what the many below cost on the base one, instead of all of them at the finest. The
// velocities come in on the finest mesh the run needs (input_mesh(); the belt is sampled onto
// it, belt_sampling.hpp); a coarser mesh's tread cells are unions of its cells and take their
// area-weighted means (tread_to_tread_matrix), which equals sampling the belt onto the coarser
// mesh directly, and each anchor's transfer is carried back to the input mesh's cells.
//
// What each anchor solves (AnchorOperators, radiation_cache.hpp) does not depend on the
// velocities: the transfer to the receivers and the power operator of the anchor's level mesh,
// W = ½ Σ_c ‖Q_c x_c‖² over the mesh's symmetry blocks (EquivalentSources::power_operator). They
// are solved first and applied to the velocities after, and with a RadiationCache they are
// loaded from and stored to disk, keyed by anchor_key(); the stage applies loaded and solved
// operators the same way, so a run from the cache gives the same numbers bit for bit.
//
// Determinism: every anchor is solved the same way whatever thread solves it, and the results
// are combined in anchor order, so the numbers do not depend on the thread count.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/fnv_digest.hpp"
#include "core/real_fft_batch.hpp"
#include "radiation/equivalent_sources.hpp"
#include "radiation/radiation_cache.hpp"
#include "radiation/transfer_table.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace rollnoise {

class ProgressReporter;

// The equivalent-source model of a tyre mesh over the road, as the radiation stage solves it,
// split by the mesh's mirror symmetries: monopoles, or combined sources (equivalent_sources.hpp)
// with η = 1 and η₀ = 50 /m; over an absorbing road when `admittance` is given.
EquivalentSources make_tyre_model(const TyreSurfaceMesh& mesh, const Medium& medium = {}, bool combined = false,
                                  PlaneAdmittance admittance = {});

// Which sources the stage uses. Monopoles up to 3 kHz, as before issue 10 §3, so the runs'
// levels there are what they were; combined sources above, where the monopoles' interior
// resonances are every few Hz and rebuilt a monopole's field 40–65 % wrong at 4–5 kHz. (The
// combined sources check better below too, but move the runs' CPX levels by 1–2 dB there: see
// docs/physics/radiation.md, "The band to 5 kHz".)
constexpr double kCombinedSourcesAboveHz = 3000.0;

struct TyreRadiationSettings {
  TyreSurfaceMeshSpec mesh;           // the mesh of the lowest band (the base)
  Medium medium;
  double combined_sources_above_hz = kCombinedSourcesAboveHz;  // anchors above: combined sources;
                                                               // at or below: monopoles
  double points_per_wavelength = 4.0;  // n of the bands' rule (above); 0: the base mesh for every anchor
  double sample_rate_hz = 0.0;        // of the velocities, when known beforehand (0: not): the
                                      // meshes then stop at the band the anchors reach (anchors())
  double max_frequency_hz = 3000.0;   // highest anchor (capped just below the Nyquist frequency)
  double anchor_spacing_hz = 100.0;   // anchors at 20, 50, then every spacing up to the maximum
  double regularisation = 1e-10;      // Tikhonov λ relative to the largest singular value
  int threads = 0;                    // parallel anchor solves; 0: the machine's cores
  // The road's normalised admittance per frequency (equivalent_sources.hpp); empty, or 0 at an
  // anchor: the rigid road there. The cache keys on its value at each anchor.
  PlaneAdmittance admittance;
};

// The most threads the anchors are solved on: `threads`, or the machine's cores when it is 0.
std::size_t radiation_thread_limit(const TyreRadiationSettings& settings);

struct RadiatedSound {
  double sample_rate = 0.0;       // Hz, that of the velocities
  double lowest_hz = 0.0;         // the band that was computed
  double highest_hz = 0.0;
  Eigen::MatrixXd pressure;       // samples × receivers, Pa, in retarded time
  Eigen::VectorXd frequency_hz;   // the transform's bins
  Eigen::VectorXd sound_power_w;  // power in each bin, W: they sum to the mean radiated power
  Eigen::VectorXd delays_s;       // each receiver's propagation delay from the wheel centre
  std::vector<double> anchors_hz;      // the anchors solved,
  std::vector<std::size_t> anchor_mesh;  // the mesh level each took (TyreRadiation::level_of)
  std::vector<double> anchor_seconds;  // and the wall time of each in its thread (not part of the results)
  std::vector<bool> anchor_from_cache;  // whether each anchor's operators came from the cache
  std::vector<Eigen::Index> anchor_power_rank;  // rows of each anchor's power operator
};

// One band's mesh (the rule above).
struct RadiationMeshLevel {
  TyreSurfaceMeshSpec spec;
  double top_hz = 0.0;  // the highest anchor it serves (the last level: every anchor above)
};
// The levels for the settings, coarse to fine: the base, then as many split meshes as the
// maximum frequency needs. std::invalid_argument if that would split the tread more than 8-fold.
std::vector<RadiationMeshLevel> radiation_mesh_levels(const TyreRadiationSettings& settings);

class TyreRadiation {
 public:
  // receivers: 3 × R positions in the mesh's coordinates (tyre_surface_mesh.hpp).
  TyreRadiation(const TyreRadiationSettings& settings, Eigen::Matrix3Xd receivers);

  // The mesh the velocities come in on: the finest of the levels (the base when there is one).
  const TyreSurfaceMesh& mesh() const noexcept { return levels_.back().mesh; }
  const TyreSurfaceMesh& input_mesh() const noexcept { return levels_.back().mesh; }
  // The bands' meshes, coarse to fine, and the level index each anchor uses.
  std::size_t levels() const noexcept { return levels_.size(); }
  const TyreSurfaceMesh& level_mesh(std::size_t level) const { return levels_.at(level).mesh; }
  const TyreSurfaceMeshSpec& level_spec(std::size_t level) const { return levels_.at(level).spec; }
  double level_top_hz(std::size_t level) const { return levels_.at(level).top_hz; }
  std::size_t level_of(double anchor_hz) const;
  // The anchor frequencies used for a velocity signal sampled at `sample_rate`.
  std::vector<double> anchors(double sample_rate) const;

  // surface_velocity: samples × A normal velocities (m/s, outward) of the first A collocation
  // points of mesh() (A = mesh().tread_points, the sidewalls at rest; or all of them when there
  // is a single level), sampled at `sample_rate`. progress (optional) counts anchors.
  // cache (optional): the anchors' operators are loaded from it when there, and stored in it
  // when solved.
  RadiatedSound radiate(const Eigen::MatrixXd& surface_velocity, double sample_rate,
                        ProgressReporter* progress = nullptr, const RadiationCache* cache = nullptr) const;

  // The key of the cache entry of an anchor (radiation_cache.hpp) on mesh level `level`, with
  // operators over the level mesh's first `columns` collocation points.
  std::string anchor_key(std::size_t level, double anchor_hz, Eigen::Index columns) const;
  // An anchor's operators, solved (what radiate() stores in and loads from the cache).
  AnchorOperators solve_anchor(std::size_t level, double anchor_hz, Eigen::Index columns) const;

 private:
  friend class TyreRadiationStream;
  // The operators' columns on mesh level `level` for `active` velocities a sample: the tread
  // (the velocities' own columns on the input mesh, which may be every point when one mesh
  // serves every anchor).
  Eigen::Index columns_of(std::size_t level, Eigen::Index active) const;
  // Every anchor's operators, loaded from the cache (in the worker, so that only the anchors in
  // hand are in memory) or solved and stored, on the settings' threads, the costliest first:
  // use(a, operators, from_cache) in the worker that has them. seconds[a]: each anchor's wall
  // time in its thread, use() included.
  void for_each_anchor(const std::vector<double>& anchor, Eigen::Index active, ProgressReporter* progress,
                       const RadiationCache* cache, std::vector<double>& seconds,
                       const std::function<void(std::size_t, AnchorOperators&&, bool)>& use) const;
  // Σ_c ‖Q_c x_c‖² (EquivalentSources::power_operator, `power` its blocks for the anchor at
  // anchor_hz on mesh level `level`) for the velocities in each of the columns `bins` of
  // `spectra` (active × bins, on the input mesh).
  Eigen::VectorXd power_squares(std::size_t level, double anchor_hz, const std::vector<Eigen::MatrixXcd>& power,
                                const Eigen::MatrixXcd& spectra, const std::vector<Eigen::Index>& bins) const;

  struct Level {
    double top_hz;
    TyreSurfaceMeshSpec spec;
    TyreSurfaceMesh mesh;
    EquivalentSources monopoles, combined;
    Eigen::SparseMatrix<double> from_input;  // tread cells of the input mesh → this mesh's (not for the input's own)
    FnvDigest geometry;  // the mesh's points, normals and sources to the bit (anchor_key)
  };
  TyreRadiationSettings settings_;
  std::vector<Level> levels_;
  Eigen::Matrix3Xd receivers_;
  Eigen::Vector3d centre_;
};

// The stage over a record too long to hold whole (issue 13: the run's memory must not grow with
// its length beyond the outputs it streams). The velocities come in sample by sample and are
// transformed in blocks of block_samples() samples; what a block holds is what radiate() holds
// for a record of that length, so the memory is flat in the run's length but for the pressures
// (samples × receivers, an output). The anchors' operators are solved (or loaded) once, up
// front, and kept for every block.
//
// Per block: the steady part taken out (each point's mean over the first block, held for the
// rest: a constant left in is one rectangle over the whole record once the blocks' pressures are
// added up, not a step at every block's edge); a zero-padded transform of each point's
// velocities; the receivers' pressures by the interpolated transfer, transformed back and
// overlap-added into the record's (the transform's last `padding / 4` samples are the reduced
// transfer's acausal part, before the block; the rest of the padding its ringing after it); and
// each bin's power ½qᴴSq as radiate() takes it, from a second transform of the block tapered at
// its ends, added up over the blocks.
//
// Why the taper: the power is quadratic, so the blocks' edges do not cancel as the pressures'
// do. Each edge cuts the velocity where it is (and any steady part left), and the cut's
// spectrum, falling as 1/f², leaks into the upper bands where the tread's velocity is
// weakest. Untapered, 1 s of plate_rough_80kmh (one block and 0.4 of another) gave 0.8 dB more
// power than the whole record at 2.5 kHz and 2.0 dB more at 4 kHz (while every receiver agreed
// to 0.001 dB). The ramps are cosines over the padding's length (30 ms), so the block keeps
// almost all of its weight; radiate() tapers the whole record the same way (power_taper.hpp),
// and its first ramp also takes out the run's start (the tyre set rolling at once rings for
// about 10 ms), so the two estimators are one.
//
// Normalisation of the power: a block of N_j samples with taper w gives its own mean power as
// Σ_k ½qᴴSq·4/(L·Σw²) over its bins (radiate()'s Parseval, with Σw² for N_j; L the block's
// transform length); the record's mean power is Σ_j (N_j/N)·that, so each block adds
// ½qᴴSq·4·N_j/(N·L·Σw²) to its bins, N the record's samples: the bins still sum to the record's
// mean radiated power. The bins are the block's (sample_rate/L apart, not the record's finer
// ones): a power spectrum averaged over the blocks, as a Welch estimate is.
//
// The numbers differ from radiate()'s on the same record by the time aliasing of the
// interpolated transfer's impulse response on the two frequency grids and at the blocks'
// edges, and the power by the two estimators (tests/radiation/test_radiation_stream.cpp).
class TyreRadiationStream {
 public:
  // Solves (or loads from `cache`) every anchor's operators now (progress counts them).
  // columns: the velocities a sample (as radiate()'s); samples: the record's length (≥ 2).
  TyreRadiationStream(const TyreRadiation& radiation, Eigen::Index columns, std::size_t samples, double sample_rate,
                      ProgressReporter* progress = nullptr, const RadiationCache* cache = nullptr);
  ~TyreRadiationStream();
  TyreRadiationStream(const TyreRadiationStream&) = delete;
  TyreRadiationStream& operator=(const TyreRadiationStream&) = delete;

  // Samples per block at `sample_rate`: at least 8192, the transform length (with the padding)
  // a fast one for FFTW.
  static std::size_t block_samples(double sample_rate);
  std::size_t block() const noexcept { return block_; }

  // The next sample: `columns` velocities, finite. A full block is transformed and applied here.
  void push(std::span<const double> velocity);
  // After the last of the `samples`: the last block, and the results (once).
  RadiatedSound finish();

 private:
  struct Anchor;
  void fill_spectra(Eigen::Index rows, bool tapered);
  void apply_block(std::size_t rows);

  const TyreRadiation& radiation_;
  Eigen::Index columns_;
  std::size_t samples_;
  double sample_rate_;
  int length_;              // of the transforms
  std::size_t block_;       // samples a block: length_ less the padding
  int head_;                // the padding's last samples, placed before the block (acausal)
  int first_bin_ = 0;
  Eigen::Index band_ = 0;   // bins first_bin_ … first_bin_ + band_ − 1
  std::vector<double> anchor_;
  std::vector<Anchor> anchors_;
  std::vector<std::size_t> order_;  // the anchors, the costliest first
  std::size_t workers_ = 1;
  std::optional<TransferTable> table_;
  RadiatedSound out_;
  Eigen::MatrixXd buffer_;  // block × columns: the block's samples
  Eigen::VectorXd mean_;    // each point's steady part (the first block's mean)
  Eigen::VectorXd taper_;   // the block's taper for the power
  bool mean_known_ = false;
  std::size_t filled_ = 0, start_ = 0;  // samples in the buffer; samples of the blocks before
  RealFftBatch velocity_fft_;           // a few points at a time
  RealFftBatch pressure_fft_;           // one transform a receiver
  Eigen::MatrixXcd spectra_;            // columns × band: the block's velocity spectra
  Eigen::MatrixXcd transfer_;           // receivers × columns at one bin
  Eigen::VectorXcd pressure_bin_;       // receivers
  bool finished_ = false;
};

}  // namespace rollnoise
