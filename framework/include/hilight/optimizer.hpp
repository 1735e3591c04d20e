#pragma once
/// Refinement of a light cut (paper §3.3): the optimizer moves lights (and
/// re-weights them) to lower the difference to the target at the samples.
#include "hilight/lighting.hpp"

#include <span>
#include <vector>

namespace hilight {

/// What an optimizer may ask of the problem; implemented by the pipeline.
class RefineProblem {
public:
  virtual ~RefineProblem() = default;
  /// Weighted ‖Ψ − Σ φ_j l_j‖² at the samples with the lights' own intensities.
  virtual double objective(std::span<const Light> lights) = 0;
  /// The same with the best non-negative intensities for these positions
  /// (NNLS); writes those intensities into `lights`.
  virtual double objective_with_best_intensities(std::vector<Light>& lights) = 0;
  /// Whether a light may stand at `p`: inside the scene bounds, not in solid geometry.
  virtual bool admissible(const Vec3& p) const = 0;
  /// The scene diagonal: the natural step size for positions.
  virtual float scale() const = 0;
  /// An objective value below which nothing is left that anyone could see:
  /// an optimizer may stop there (0: never stop early).
  virtual double negligible() const { return 0.0; }
};

/// How much work a refine call should do.
enum class RefineEffort {
  Full,    ///< from a cut: lights may be far from their optimum
  Polish,  ///< from a refined result: a short local pass
};

class Optimizer {
public:
  virtual ~Optimizer() = default;
  /// Refines `start` (positions, intensities, spot directions and cutoffs).
  virtual Lighting refine(RefineProblem& problem, const Lighting& start, RefineEffort effort) = 0;
};

} // namespace hilight
