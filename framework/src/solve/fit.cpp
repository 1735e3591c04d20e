#include "hilight/solve/fit.hpp"

#include "hilight/solve/nnls.hpp"

#include <cmath>

namespace hilight {

std::vector<Rgb> fit_intensities(const std::vector<Rgb>& phi, size_t n, const SampleSet& samples, std::span<const Rgb> scale) {
  const size_t m = samples.size();
  std::vector<Rgb> out(n, Rgb(0.f));
  if (n == 0) return out;
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd a(m, n);
    Eigen::VectorXd b(m);
    for (size_t i = 0; i < m; ++i) {
      double sw = std::sqrt(double(samples.weight[i]) * (scale.empty() ? 1.0 : double(scale[i][c])));
      b(Eigen::Index(i)) = sw * samples.target[i][c];
      for (size_t j = 0; j < n; ++j) a(Eigen::Index(i), Eigen::Index(j)) = sw * phi[j * m + i][c];
    }
    Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
    ata.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
    ata.triangularView<Eigen::Upper>() = ata.transpose();
    Eigen::VectorXd atb = a.transpose() * b;
    NnlsResult r = solve_nnls(ata, atb);
    for (size_t j = 0; j < n; ++j) out[j][c] = float(r.x(Eigen::Index(j)));
  }
  return out;
}

std::vector<Rgb> combine(const std::vector<Rgb>& phi, std::span<const Rgb> intensities, size_t m) {
  std::vector<Rgb> out(m, Rgb(0.f));
  for (size_t j = 0; j < intensities.size(); ++j) {
    const Rgb l = intensities[j];
    if (l == Rgb(0.f)) continue;
    const Rgb* col = &phi[j * m];
    for (size_t i = 0; i < m; ++i) out[i] += col[i] * l;
  }
  return out;
}

double difference(const std::vector<Rgb>& illumination, const SampleSet& samples) {
  double sum = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    DVec3 d = DVec3(illumination[i]) - DVec3(samples.target[i]);
    sum += samples.weight[i] * glm::dot(d, d);
  }
  return std::sqrt(sum);
}

double normalized_difference(const std::vector<Rgb>& illumination, const SampleSet& samples) {
  double norm = samples.target_norm(), d = difference(illumination, samples);
  if (norm > 0) return d / norm;
  return d > 0 ? 1.0 : 0.0;  // a black target: any light is all error, none is none
}

double contribution(const std::vector<Rgb>& phi, size_t j, const Rgb& intensity, const SampleSet& samples) {
  const size_t m = samples.size();
  double sum = 0;
  for (size_t i = 0; i < m; ++i) {
    DVec3 v = DVec3(phi[j * m + i] * intensity);
    sum += samples.weight[i] * glm::dot(v, v);
  }
  return std::sqrt(sum);
}

} // namespace hilight
