#pragma once
// A tyre model known by its receptance between points of its surface at any frequency, the
// static case included: the interface of layered, modal tyre models such as the two-layer tyre
// (two_layer_tyre.hpp). It sits beside GreensModel (greens_model.hpp), which serves a fixed set
// of contact points with closed-form time responses: a layered model has no closed-form g(t),
// and its natural product is the response at one frequency for any pair of surface points.
//
// Coordinates are the tyre's material frame (MODEL.md §1): x along the circumference
// (0 ≤ x < L = 2πR, periodic), y across the width (0 ≤ y ≤ b). Directions x, y and z, z normal
// to the surface; the normal–normal receptance is the same whether z is taken outward or, as the
// contact does, towards the axle (both force and displacement change sign).
//
// A source or receiver is a point or a cell: a cell's force is spread uniformly over it, and a
// cell's displacement is its mean over the cell. The contact grid needs cells: on the tread
// surface the point-to-point receptance diverges like 1/r (Boussinesq), so a point load does not
// converge in a modal sum, while the cell-averaged one does.
#include <complex>
#include <memory>
#include <string>

namespace rollnoise {

enum class SurfaceDirection { x = 0, y = 1, z = 2 };

struct SurfaceLocation {
  double x = 0.0;       // m, centre
  double y = 0.0;       // m, centre
  double length = 0.0;  // m, the cell's extent along x (0: a point)
  double width = 0.0;   // m, the cell's extent along y (0: a point)
};

// The model at one frequency: cheap to query for many point pairs.
class SurfaceResponse {
 public:
  virtual ~SurfaceResponse() = default;
  // ω, rad/s (0: the static response).
  virtual std::complex<double> frequency() const = 0;
  // Displacement at `receiver` along `response` per unit force at `source` along `load`, m/N.
  virtual std::complex<double> receptance(const SurfaceLocation& receiver, const SurfaceLocation& source,
                                          SurfaceDirection response = SurfaceDirection::z,
                                          SurfaceDirection load = SurfaceDirection::z) const = 0;
  // Mobility iω·α, m/(N·s).
  std::complex<double> mobility(const SurfaceLocation& receiver, const SurfaceLocation& source,
                                SurfaceDirection response = SurfaceDirection::z,
                                SurfaceDirection load = SurfaceDirection::z) const {
    return std::complex<double>(0.0, 1.0) * frequency() * receptance(receiver, source, response, load);
  }
};

class SurfaceReceptanceModel {
 public:
  virtual ~SurfaceReceptanceModel() = default;
  virtual std::string name() const = 0;
  virtual double circumference() const = 0;  // L, m
  virtual double width() const = 0;          // b, m
  // The response at angular frequency ω (rad/s; ω = 0 exactly is the static case; Im ω ≤ 0 is
  // allowed for an exponential window). It may refer to the model, which must outlive it.
  virtual std::unique_ptr<SurfaceResponse> at(std::complex<double> omega) const = 0;
};

}  // namespace rollnoise
