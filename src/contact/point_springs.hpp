#pragma once
// The springs in series with the structure at the contact points of a nonlinear contact step
// (tread_newton_contact.hpp): F_p = f_p(δ_p), each f_p increasing with f_p(0) = 0, extended as an
// odd function (F(−δ) = −F(δ)) for Newton's trial points on the contact set. Two kinds:
//  - PowerLawSprings: the nonlinear tread, F = k_p·δⁿ (MODEL.md §4);
//  - the per-cell contact laws of the road's fine texture (cell_contact_law.hpp), which change
//    with the road under each point every step.
#include <Eigen/Core>

namespace rollnoise {

class PointSprings {
 public:
  virtual ~PointSprings() = default;
  virtual Eigen::Index size() const = 0;
  // F_p(δ) and dF/dδ at point p (odd in δ).
  virtual void evaluate(Eigen::Index p, double delta, double& force, double& slope) const = 0;
  // δ with δ + c·F_p(δ) = y (c = A_pp > 0, the structure's own compliance at p), odd in y.
  // `guess`: a δ near the root (0: none).
  virtual double compression_of(Eigen::Index p, double y, double c, double guess) const = 0;
  // compression_of and then evaluate at the δ found; a law that knows where its root search
  // ended evaluates there without searching again.
  virtual void compress(Eigen::Index p, double y, double c, double guess, double& delta, double& force,
                        double& slope) const {
    delta = compression_of(p, y, c, guess);
    evaluate(p, delta, force, slope);
  }
  // δ ≥ 0 with F_p(δ) = force ≥ 0.
  virtual double compression_at(Eigen::Index p, double force) const = 0;
  // ∫₀^|δ| F_p: the energy the spring stores (even in δ). The solver's energy uses the
  // complementary ∫₀^F δ = F·δ − this.
  virtual double stored_energy(Eigen::Index p, double delta) const = 0;
};

// F_p = k_p·δⁿ, k_p > 0 (N/m^n), n ≥ 1.
class PowerLawSprings final : public PointSprings {
 public:
  PowerLawSprings(Eigen::VectorXd stiffness, double exponent);  // std::invalid_argument if k ≤ 0 or n < 1
  Eigen::Index size() const override { return k_.size(); }
  void evaluate(Eigen::Index p, double delta, double& force, double& slope) const override;
  double compression_of(Eigen::Index p, double y, double c, double guess) const override;
  double compression_at(Eigen::Index p, double force) const override;
  double stored_energy(Eigen::Index p, double delta) const override;

 private:
  // |δ|^{n−1}
  double lower_power(double magnitude) const;
  Eigen::VectorXd k_;
  double n_;
  enum class Power { general, one_and_a_half, two_and_a_half, three };  // n − 1 by square roots
  Power power_ = Power::general;
};

}  // namespace rollnoise
