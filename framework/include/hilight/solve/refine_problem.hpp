#pragma once
/// RefineProblem over a sample set: φ per light from the ResponseModel, kept
/// per light (so moving one light of several costs one light's φ), and the
/// admissibility rule for light positions.
#include "hilight/optimizer.hpp"
#include "hilight/solve/responses.hpp"
#include "hilight/light_space.hpp"

#include <string>
#include <unordered_map>

namespace hilight {

class SampleRefineProblem final : public RefineProblem {
public:
  /// `exact`: the same samples without the light cache, used to anchor lights
  /// (may be null: no anchoring).
  SampleRefineProblem(ResponseModel& model, const LightSpace& space, ResponseModel* exact = nullptr)
      : m_model(model), m_space(space), m_exact(exact) {}

  /// Anchors light j of every later call at `lights[j]`: its response gets
  /// the correction exact(anchor) − model(anchor), which removes the light
  /// cache's interpolation error near the anchor (lights move little in
  /// refinement). Call again after large moves.
  void anchor(const Lighting& lights);

  double objective(std::span<const Light> lights) override;
  double objective_with_best_intensities(std::vector<Light>& lights) override;
  bool admissible(const Vec3& p) const override;
  float scale() const override { return m_space.rays().scene().diagonal(); }
  /// D̄ 0.01% at the samples (the threshold polish_with_reference stops at).
  double negligible() const override;
  /// Moves every light where the light space puts it (the ceiling mount);
  /// false if one cannot stand anywhere near. Objectives evaluate placed lights.
  bool place(std::vector<Light>& lights) const;
  const LightSpace& space() const { return m_space; }

  /// Unit responses of `lights` (light-major), from the per-light store.
  std::vector<Rgb> responses(std::span<const Light> lights);
  /// The same, light q corrected as anchored light `anchor_index[q]` (moved
  /// copies of the anchored lights: finite differences), in one batch.
  std::vector<Rgb> responses_as(std::span<const Light> lights, std::span<const size_t> anchor_index);
  const SampleSet& samples() const { return m_model.samples(); }

private:
  const std::vector<Rgb>& phi_of(const Light& light);
  ResponseModel& m_model;
  const LightSpace& m_space;
  ResponseModel* m_exact;
  std::vector<std::vector<Rgb>> m_correction;  ///< per light index (empty: none)
  std::unordered_map<std::string, std::vector<Rgb>> m_phi;  ///< keyed by the light's geometry bytes
};

} // namespace hilight
