// multiply_sparse_rows (src/core/sparse_rows_product.hpp) against Eigen's products, bit for bit:
// the tyre run's radiating velocity goes through it, and the outputs promise byte identity.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/sparse_rows_product.hpp"

namespace rollnoise {
namespace {

TEST(SparseRowsProduct, IsEigensProductBitForBit) {
  std::mt19937 random(12);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (const int rows : {1, 3, 4, 7, 64, 1001}) {
    const int columns = 3 * rows + 5;
    std::vector<Eigen::Triplet<double>> entries;
    std::uniform_int_distribution<int> column(0, columns - 1), count(0, 9);
    for (int r = 0; r < rows; ++r)
      for (int k = count(random); k > 0; --k) entries.emplace_back(r, column(random), value(random));  // duplicates too
    Eigen::SparseMatrix<double> col_major(rows, columns);
    col_major.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double, Eigen::RowMajor> row_major = col_major;
    Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(columns, [&] { return value(random); });
    x(0) = 0.0;
    x(1) = -0.0;  // signed zeros: the sums start from +0 as Eigen's
    Eigen::VectorXd eigen(rows), eigen_rows(rows), ours(rows);
    eigen.noalias() = col_major * x;
    eigen_rows.noalias() = row_major * x;
    multiply_sparse_rows(row_major, x.data(), ours.data());
    EXPECT_EQ(std::memcmp(eigen.data(), ours.data(), sizeof(double) * static_cast<std::size_t>(rows)), 0) << rows;
    EXPECT_EQ(std::memcmp(eigen_rows.data(), ours.data(), sizeof(double) * static_cast<std::size_t>(rows)), 0) << rows;
  }
}

}  // namespace
}  // namespace rollnoise
