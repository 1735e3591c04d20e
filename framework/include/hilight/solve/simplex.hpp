#pragma once
/// The Nelder–Mead downhill simplex (Nelder & Mead 1965), with the
/// dimension-adaptive coefficients of Gao & Han 2012, which keep it
/// effective above a handful of dimensions. Shared by the optimizer plugins.
#include <functional>
#include <vector>

namespace hilight {

struct SimplexSettings {
  int max_evaluations = 1000;
  double f_tolerance = 1e-9;  ///< stop when the simplex's values agree this closely (relative)
  double x_tolerance = 1e-6;  ///< ...and its vertices this closely (in parameter units)
  double f_target = 0.0;      ///< stop as soon as a value is at or below this (good enough)
};

struct SimplexResult {
  std::vector<double> x;
  double value = 0.0;
  int evaluations = 0;
};

/// Minimizes f from x0 with initial steps `steps` (one per parameter).
SimplexResult nelder_mead(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& x0,
                          const std::vector<double>& steps, const SimplexSettings& settings);

} // namespace hilight
