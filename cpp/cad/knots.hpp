// Knot vectors and the dense B-spline matrices of the fit: clamped and periodic bases over a
// list of breakpoints, collocation (basis values or derivatives at sample parameters), knot
// insertion, and a periodic spline's clamped form (what the writers take).
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace pdesurf {

// breaks b_0 < … < b_n (n spans): b_0 and b_n repeated degree + 1 times, n + degree poles.
// An inner break marked in `creases` is repeated degree times: the spline is only C0 there.
std::vector<double> clampedKnots(const std::vector<double>& breaks, int degree, const std::vector<bool>* creases = nullptr);
// The same spans extended periodically by degree knots on each side (period b_n - b_0):
// n + degree unwrapped poles, of which the last degree repeat the first.
std::vector<double> periodicKnots(const std::vector<double>& breaks, int degree);

// out(i, j) = d^derivative N_j(t_i) / dt^derivative. For periodic knots the columns of the
// unwrapped poles past the n-th are folded onto the first (`fold`: n, or 0 for none).
// Sparse: degree + 1 entries per row.
Eigen::SparseMatrix<double> collocation(const std::vector<double>& knots, int degree, const std::vector<double>& t,
                                        int derivative, int fold = 0);

// Inserts the knot t once (Boehm); rows of `poles` are the poles (any number of columns).
void insertKnot(std::vector<double>& knots, Eigen::MatrixXd& poles, int degree, double t);

// A periodic spline (periodicKnots over breaks, n periodic poles as rows) in clamped form on
// [b_0, b_n]: n + degree poles, the first equal to the last. Exact: the same curve.
void periodicToClamped(const std::vector<double>& breaks, int degree, const Eigen::MatrixXd& periodicPoles,
                       std::vector<double>* knots, Eigen::MatrixXd* poles);

}  // namespace pdesurf
