#pragma once
/// `hilight solve --report-html out.html`: a self-contained page for a
/// person (images embedded as PNG data, plots as inline SVG, no scripts
/// from elsewhere): the target, the result and their difference from three
/// views; D̄ against the light count (the hierarchy's cuts) with the chosen
/// count marked; the lights; the timings.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/solve/illuminance_design.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/ray_scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hilight {

struct HtmlReport {
  const Scene* scene = nullptr;
  const RayScene* rays = nullptr;
  std::string title;              ///< e.g. the scene and target files
  std::vector<Rgb> target;        ///< per scene vertex (0 where no target point)
  std::vector<float> target_weight;  ///< per scene vertex, 0: no target there
  std::vector<Rgb> result;        ///< per scene vertex, what the lights give
  Lighting lights;
  SolveReport report;
  std::string units = "radiometric";
  /// Set for a solve for illuminance criteria: the result alone is shown,
  /// and each grid as a false-colour map with Ē, Emin and U0 (`design`).
  const IlluminanceCriteria* criteria = nullptr;
  DesignReport design;
};

/// Written atomically. Images are `width` pixels wide.
void write_html_report(const std::filesystem::path& path, const HtmlReport& page, int width = 480);

/// Per-vertex values seen through a camera (each pixel the barycentric blend
/// of its triangle's vertices): how a target or result looks from a view.
Image vertex_value_image(const Scene& scene, const RayScene& rays, const Camera& camera, const std::vector<Rgb>& values,
                         int width, int height);

} // namespace hilight
