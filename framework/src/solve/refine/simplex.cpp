#include "hilight/solve/simplex.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hilight {

SimplexResult nelder_mead(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& x0,
                          const std::vector<double>& steps, const SimplexSettings& settings) {
  const size_t n = x0.size();
  SimplexResult result;
  if (n == 0) {
    result.x = x0;
    result.value = f(x0);
    result.evaluations = 1;
    return result;
  }
  const double dn = double(n);
  const double alpha = 1.0, beta = 1.0 + 2.0 / dn, gamma = 0.75 - 1.0 / (2.0 * dn), delta = 1.0 - 1.0 / dn;
  std::vector<std::vector<double>> simplex(n + 1, x0);
  std::vector<double> values(n + 1);
  int evals = 0;
  auto eval = [&](const std::vector<double>& x) {
    ++evals;
    double v = f(x);
    return std::isfinite(v) ? v : 1e300;
  };
  values[0] = eval(simplex[0]);
  for (size_t i = 0; i < n; ++i) {
    simplex[i + 1][i] += steps[i];
    values[i + 1] = eval(simplex[i + 1]);
  }
  std::vector<size_t> order(n + 1);
  std::vector<double> centroid(n), trial(n), trial2(n);
  while (evals < settings.max_evaluations) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
    const size_t best = order[0], worst = order[n], second = order[n - 1];
    // Converged when the values and the vertices have both collapsed.
    double spread = std::abs(values[worst] - values[best]);
    double size = 0;
    for (size_t i = 0; i <= n; ++i)
      for (size_t k = 0; k < n; ++k) size = std::max(size, std::abs(simplex[i][k] - simplex[best][k]));
    if (spread <= settings.f_tolerance * (std::abs(values[best]) + 1e-300) && size <= settings.x_tolerance) break;
    if (size <= settings.x_tolerance * 1e-3) break;
    if (values[best] <= settings.f_target) break;

    std::fill(centroid.begin(), centroid.end(), 0.0);
    for (size_t i = 0; i <= n; ++i)
      if (i != worst)
        for (size_t k = 0; k < n; ++k) centroid[k] += simplex[i][k] / dn;
    for (size_t k = 0; k < n; ++k) trial[k] = centroid[k] + alpha * (centroid[k] - simplex[worst][k]);
    double fr = eval(trial);
    if (fr < values[best]) {
      for (size_t k = 0; k < n; ++k) trial2[k] = centroid[k] + beta * (trial[k] - centroid[k]);
      double fe = eval(trial2);
      if (fe < fr) simplex[worst] = trial2, values[worst] = fe;
      else simplex[worst] = trial, values[worst] = fr;
      continue;
    }
    if (fr < values[second]) {
      simplex[worst] = trial;
      values[worst] = fr;
      continue;
    }
    bool outside = fr < values[worst];
    for (size_t k = 0; k < n; ++k)
      trial2[k] = outside ? centroid[k] + gamma * (trial[k] - centroid[k]) : centroid[k] - gamma * (centroid[k] - simplex[worst][k]);
    double fc = eval(trial2);
    if (fc < std::min(fr, values[worst])) {
      simplex[worst] = trial2;
      values[worst] = fc;
      continue;
    }
    for (size_t i = 0; i <= n; ++i) {
      if (i == best) continue;
      for (size_t k = 0; k < n; ++k) simplex[i][k] = simplex[best][k] + delta * (simplex[i][k] - simplex[best][k]);
      values[i] = eval(simplex[i]);
    }
  }
  size_t best = size_t(std::min_element(values.begin(), values.end()) - values.begin());
  result.x = simplex[best];
  result.value = values[best];
  result.evaluations = evals;
  return result;
}

} // namespace hilight
