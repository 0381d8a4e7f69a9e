#pragma once
// The Green's-function model interface (ARCHITECTURE.md, "The two central interfaces").
//
// A model's Green's function between contact points is g(t) = C_local·δ(t) + g_s(t): an
// instantaneous local compliance (the contact spring, the tread) plus a smooth structural
// part. Everything the contact solver needs follows from these two parts (MODEL.md §2).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class GreensModel {
 public:
  virtual ~GreensModel() = default;

  // "sdof", "coupled_sdof", ...
  virtual std::string name() const = 0;
  virtual Eigen::Index point_count() const = 0;

  // C_local: the δ(t) part of g, m/N (symmetric, point_count × point_count).
  virtual Eigen::MatrixXd local_compliance() const = 0;
  // g_s(t) for t >= 0, m/(N·s).
  virtual Eigen::MatrixXd smooth_response(double t) const = 0;
  // ∫_{t0}^{t1} g_s(τ) dτ for 0 <= t0 <= t1, m/N; t1 may be +infinity.
  virtual Eigen::MatrixXd smooth_integral(double t0, double t1) const = 0;
  // The static compliance C_local + ∫_0^∞ g_s, m/N.
  Eigen::MatrixXd static_compliance() const;
  // Receptance α(ω) = ∫ g(t) e^{−iωt} dt, m/N, at angular frequency ω (rad/s).
  virtual Eigen::MatrixXcd receptance(double omega) const = 0;

  // The slowest decay rate of g_s (1/s): g_s(t) ≤ C·e^{−rate·t} for large t.
  virtual double slowest_decay_rate() const = 0;
  // The fastest rate (rad/s) of the model's dynamics, with and without contact: a time step
  // must resolve it.
  virtual double fastest_rate() const = 0;

  // Offsets of the contact points behind the first one along the road (m): point i sees the
  // road at x − offset_i.
  virtual std::vector<double> contact_point_offsets() const = 0;
};

}  // namespace rollnoise
