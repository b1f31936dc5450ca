#include "planners/hungarian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace camcov::planners {
namespace {

double totalCost(const std::vector<double>& cost, int cols, const std::vector<int>& assignment) {
  double total = 0;
  for (std::size_t r = 0; r < assignment.size(); ++r)
    total += cost[r * cols + assignment[r]];
  return total;
}

// The obviously-correct reference: try every injective map of rows to columns.
double bruteForceMinimum(const std::vector<double>& cost, int rows, int cols) {
  std::vector<int> columns(cols);
  std::iota(columns.begin(), columns.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {
    double total = 0;
    for (int r = 0; r < rows; ++r)
      total += cost[r * cols + columns[r]];
    best = std::min(best, total);
  } while (std::next_permutation(columns.begin(), columns.end()));
  return best;
}

TEST(SolveAssignment, MatchesBruteForceOnRandomMatrices) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> value(0.0, 10.0);
  std::uniform_int_distribution<int> integer(0, 3);  // many ties
  for (int trial = 0; trial < 2000; ++trial) {
    const int cols = 1 + trial % 7;
    const int rows = 1 + (trial / 7) % cols;
    std::vector<double> cost(static_cast<std::size_t>(rows) * cols);
    for (auto& c : cost)
      c = trial % 2 ? value(rng) : integer(rng);
    const auto assignment = solveAssignment(cost, rows, cols);
    ASSERT_EQ(assignment.size(), static_cast<std::size_t>(rows));
    std::vector<int> sorted = assignment;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "injective";
    EXPECT_TRUE(sorted.front() >= 0 && sorted.back() < cols);
    EXPECT_NEAR(totalCost(cost, cols, assignment), bruteForceMinimum(cost, rows, cols), 1e-9)
        << "trial " << trial;
  }
}

TEST(SolveAssignment, PicksTheObviousDiagonal) {
  const std::vector<double> cost{1, 9, 9, 9, 1, 9, 9, 9, 1};
  EXPECT_EQ(solveAssignment(cost, 3, 3), (std::vector<int>{0, 1, 2}));
}

TEST(SolveAssignment, HandlesEmptyAndRejectsBadShapes) {
  EXPECT_TRUE(solveAssignment({}, 0, 0).empty());
  const std::vector<double> cost{1, 2, 3, 4, 5, 6};
  EXPECT_THROW(solveAssignment(cost, 3, 2), std::invalid_argument);  // more rows than columns
  EXPECT_THROW(solveAssignment(cost, 2, 2), std::invalid_argument);  // wrong size
}

}  // namespace
}  // namespace camcov::planners
