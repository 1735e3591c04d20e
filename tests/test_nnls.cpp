// NNLS (FNNLS) against a brute-force reference: for small problems, the exact
// optimum is the best unconstrained least-squares solution over every subset
// of free variables that comes out non-negative.
#include "hilight/solve/nnls.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace hilight;

namespace {

double objective(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& x) { return (a * x - b).squaredNorm(); }

Eigen::VectorXd brute_force(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const int n = int(a.cols());
  Eigen::VectorXd best = Eigen::VectorXd::Zero(n);
  double best_value = objective(a, b, best);
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> idx;
    for (int j = 0; j < n; ++j)
      if (mask & (1 << j)) idx.push_back(j);
    Eigen::MatrixXd sub(a.rows(), Eigen::Index(idx.size()));
    for (size_t k = 0; k < idx.size(); ++k) sub.col(Eigen::Index(k)) = a.col(idx[k]);
    Eigen::VectorXd z = sub.colPivHouseholderQr().solve(b);
    if ((z.array() < 0).any()) continue;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    for (size_t k = 0; k < idx.size(); ++k) x(idx[k]) = z(Eigen::Index(k));
    if (double v = objective(a, b, x); v < best_value) best_value = v, best = x;
  }
  return best;
}

} // namespace

TEST_CASE("NNLS matches a brute-force reference on small random problems", "[nnls]") {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int active_seen = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int m = 6 + trial % 10, n = 2 + trial % 6;
    Eigen::MatrixXd a(m, n);
    Eigen::VectorXd b(m);
    // Half the trials look like lighting: non-negative responses and target.
    const bool lighting = trial % 2 == 0;
    for (int i = 0; i < m; ++i) {
      b(i) = lighting ? uniform(rng) : normal(rng);
      for (int j = 0; j < n; ++j) a(i, j) = lighting ? uniform(rng) : normal(rng);
    }
    NnlsResult r = solve_nnls(a.transpose() * a, a.transpose() * b);
    Eigen::VectorXd ref = brute_force(a, b);
    REQUIRE(r.converged);
    REQUIRE((r.x.array() >= 0).all());
    INFO("trial " << trial);
    REQUIRE(objective(a, b, r.x) == Approx(objective(a, b, ref)).epsilon(1e-9).margin(1e-12));
    REQUIRE((r.x - ref).norm() <= 1e-6 * (1 + ref.norm()));
    active_seen += (r.x.array() == 0).any();
  }
  CHECK(active_seen > 50);  // the constraint was actually binding in many trials
}

TEST_CASE("NNLS recovers an exact non-negative combination and handles duplicate columns", "[nnls]") {
  Eigen::MatrixXd a(5, 3);
  a << 1, 0, 1, 0, 1, 0, 1, 1, 1, 2, 0, 2, 0, 3, 0;  // column 2 duplicates column 0
  Eigen::VectorXd truth(3);
  truth << 0.5, 2.0, 0.0;
  Eigen::VectorXd b = a * truth;
  NnlsResult r = solve_nnls(a.transpose() * a, a.transpose() * b);
  CHECK(objective(a, b, r.x) < 1e-18);
  CHECK(r.x(1) == Approx(2.0));
  CHECK(r.x(0) + r.x(2) == Approx(0.5));
}

TEST_CASE("NNLS of an all-negative correlation is zero", "[nnls]") {
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(3, 3);
  Eigen::VectorXd b(3);
  b << -1, -2, -3;
  NnlsResult r = solve_nnls(a, b);
  CHECK(r.x.isZero());
}
