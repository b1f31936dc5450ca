#include "planners/hungarian.h"

#include <limits>
#include <stdexcept>

namespace camcov::planners {

std::vector<int> solveAssignment(std::span<const double> cost, int rows, int cols) {
  if (rows < 0 || cols < rows || cost.size() != static_cast<std::size_t>(rows) * cols) {
    throw std::invalid_argument("solveAssignment: need a rows x cols matrix with rows <= cols");
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  auto c = [&](int r, int col) { return cost[static_cast<std::size_t>(r) * cols + col]; };
  // Potentials u (rows) and v (columns) keep every reduced cost c - u - v >= 0; rows are
  // added one at a time and matched along a shortest augmenting path (Dijkstra on reduced
  // costs). Index 0 of the column arrays is a virtual column holding the row being added.
  std::vector<double> u(rows + 1, 0.0), v(cols + 1, 0.0), minReduced(cols + 1);
  std::vector<int> rowOfColumn(cols + 1, 0), previousColumn(cols + 1, 0);
  std::vector<char> visited(cols + 1);
  for (int r = 1; r <= rows; ++r) {
    rowOfColumn[0] = r;
    int column = 0;
    std::fill(minReduced.begin(), minReduced.end(), kInf);
    std::fill(visited.begin(), visited.end(), 0);
    do {
      visited[column] = 1;
      const int row = rowOfColumn[column];
      double delta = kInf;
      int next = 0;
      for (int j = 1; j <= cols; ++j) {
        if (visited[j]) continue;
        const double reduced = c(row - 1, j - 1) - u[row] - v[j];
        if (reduced < minReduced[j]) {
          minReduced[j] = reduced;
          previousColumn[j] = column;
        }
        if (minReduced[j] < delta) {
          delta = minReduced[j];
          next = j;
        }
      }
      for (int j = 0; j <= cols; ++j) {
        if (visited[j]) {
          u[rowOfColumn[j]] += delta;
          v[j] -= delta;
        } else {
          minReduced[j] -= delta;
        }
      }
      column = next;
    } while (rowOfColumn[column] != 0);
    // Flip the augmenting path back to the virtual column.
    do {
      const int previous = previousColumn[column];
      rowOfColumn[column] = rowOfColumn[previous];
      column = previous;
    } while (column != 0);
  }
  std::vector<int> assignment(rows, -1);
  for (int j = 1; j <= cols; ++j) {
    if (rowOfColumn[j] != 0) assignment[rowOfColumn[j] - 1] = j - 1;
  }
  return assignment;
}

}  // namespace camcov::planners
