#pragma once
// Task assignment (paper section V-B): the Hungarian method (Kuhn 1955, Munkres 1957) with
// row/column potentials, O(n² m) for n rows (cameras) and m >= n columns (goals).
#include <span>
#include <vector>

namespace camcov::planners {

// Row-major cost matrix of `rows` x `cols`, rows <= cols, finite entries. Returns for each
// row the column assigned to it, minimising the total cost; ties resolve deterministically.
std::vector<int> solveAssignment(std::span<const double> cost, int rows, int cols);

}  // namespace camcov::planners
