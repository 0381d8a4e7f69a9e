// The power operator at its stored precision (radiation/quantised_power_operator.hpp): the
// rotation keeps Σ‖Qx‖², every value is a 16-bit multiple of the quantum, the weak patterns' rows
// that round to nothing are dropped, and the power moves by no more than the rounding allows.
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "radiation/quantised_power_operator.hpp"

namespace rollnoise {
namespace {
using Complex = std::complex<double>;

Eigen::MatrixXcd random_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937& random) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXcd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = Complex(normal(random), normal(random));
  return m;
}

// Blocks like the power operator's: singular values falling over ten decades (a few strong
// radiating patterns, many weak ones), rows mixed as the pivoted Cholesky leaves them.
std::vector<Eigen::MatrixXcd> falling_blocks(std::mt19937& random) {
  std::vector<Eigen::MatrixXcd> blocks;
  for (const Eigen::Index rank : {40, 25, 0, 12}) {
    const Eigen::Index cols = 120;
    if (rank == 0) {
      blocks.emplace_back(0, cols);
      continue;
    }
    Eigen::MatrixXcd scaled = random_matrix(rank, cols, random);
    for (Eigen::Index i = 0; i < rank; ++i) scaled.row(i) *= std::pow(10.0, -10.0 * static_cast<double>(i) / 40.0);
    blocks.push_back(random_matrix(rank, rank, random) * scaled);
  }
  return blocks;
}

double power(const std::vector<Eigen::MatrixXcd>& blocks, const std::vector<Eigen::VectorXcd>& x) {
  double w = 0.0;
  for (std::size_t c = 0; c < blocks.size(); ++c)
    if (blocks[c].rows() > 0) w += (blocks[c] * x[c]).squaredNorm();
  return w;
}

TEST(QuantisedPowerOperator, KeepsThePowerWithinTheRoundingAndStoresSixteenBits) {
  std::mt19937 random(11);
  const std::vector<Eigen::MatrixXcd> blocks = falling_blocks(random);
  const QuantisedPower q = quantise_power_operator(blocks);
  ASSERT_EQ(q.blocks.size(), blocks.size());
  ASSERT_GT(q.quantum, 0.0);
  double largest = 0.0;
  for (std::size_t c = 0; c < blocks.size(); ++c) {
    EXPECT_EQ(q.blocks[c].cols(), blocks[c].cols());
    EXPECT_LE(q.blocks[c].rows(), blocks[c].rows());
    if (q.blocks[c].rows() == 0) continue;
    // Integer multiples of the quantum within 16 bits, exactly as stored and loaded.
    const Int16Matrix re = integers_of(q.blocks[c].real(), q.quantum);
    const Int16Matrix im = integers_of(q.blocks[c].imag(), q.quantum);
    EXPECT_TRUE(values_of(re, q.quantum) == Eigen::MatrixXd(q.blocks[c].real()));
    EXPECT_TRUE(values_of(im, q.quantum) == Eigen::MatrixXd(q.blocks[c].imag()));
    largest = std::max({largest, q.blocks[c].real().cwiseAbs().maxCoeff(), q.blocks[c].imag().cwiseAbs().maxCoeff()});
    // No row of zeros is kept; the rows come strongest first.
    for (Eigen::Index i = 0; i < q.blocks[c].rows(); ++i) EXPECT_GT(q.blocks[c].row(i).squaredNorm(), 0.0);
    for (Eigen::Index i = 1; i < q.blocks[c].rows(); ++i)
      EXPECT_LE(q.blocks[c].row(i).norm(), q.blocks[c].row(i - 1).norm() * (1.0 + 1e-6) + 2.0 * q.quantum * std::sqrt(120.0));
  }
  // The quantum is σ₁/32767: the strongest row's norm, which bounds every part.
  double strongest = 0.0;
  for (const Eigen::MatrixXcd& b : q.blocks)
    if (b.rows() > 0) strongest = std::max(strongest, b.rowwise().norm().maxCoeff());
  EXPECT_NEAR(strongest, 32767.0 * q.quantum, 1e-4 * strongest);
  EXPECT_LE(largest, 32767.0 * q.quantum);
  // The weak patterns (σ below the quantum over the row) are gone: fewer rows than the rank.
  Eigen::Index kept = 0, rank = 0;
  for (std::size_t c = 0; c < blocks.size(); ++c) {
    kept += q.blocks[c].rows();
    rank += blocks[c].rows();
  }
  EXPECT_LT(kept, rank);
  EXPECT_GT(kept, rank / 3);

  // The power of velocities that radiate well (the strongest pattern's direction) moves by
  // about the quantum relative to σ₁ (1e-4 bounds it); random ones, which radiate a few per cent as
  // well, within 1e-3.
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::VectorXcd> x;
    for (const Eigen::MatrixXcd& b : blocks) x.push_back(random_matrix(b.cols(), 1, random).col(0));
    const double exact = power(blocks, x), stored = power(q.blocks, x);
    EXPECT_NEAR(stored, exact, 1e-3 * exact) << "trial " << trial;
  }
  Eigen::VectorXcd strong = blocks[0].row(0).adjoint();
  std::vector<Eigen::VectorXcd> x{strong, Eigen::VectorXcd::Zero(120), Eigen::VectorXcd::Zero(120), Eigen::VectorXcd::Zero(120)};
  EXPECT_NEAR(power(q.blocks, x), power(blocks, x), 1e-4 * power(blocks, x));
}

TEST(QuantisedPowerOperator, EmptyBlocksAndBadValues) {
  const QuantisedPower none = quantise_power_operator({Eigen::MatrixXcd(0, 5), Eigen::MatrixXcd::Zero(3, 4)});
  EXPECT_EQ(none.quantum, 0.0);
  ASSERT_EQ(none.blocks.size(), 2u);
  EXPECT_EQ(none.blocks[0].rows(), 0);
  EXPECT_EQ(none.blocks[1].rows(), 0);
  EXPECT_EQ(none.blocks[1].cols(), 4);
  Eigen::MatrixXd part(1, 2);
  part << 3.0, -32767.0;
  EXPECT_EQ(values_of(integers_of(part, 1.0), 1.0), part);
  part(0, 0) = 3.5;
  EXPECT_THROW(integers_of(part, 1.0), std::invalid_argument) << "not a multiple";
  part << 3.0, 32768.0;
  EXPECT_THROW(integers_of(part, 1.0), std::invalid_argument) << "beyond 16 bits";
  EXPECT_THROW(integers_of(part, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
