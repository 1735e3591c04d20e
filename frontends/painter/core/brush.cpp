#include "core/brush.hpp"

#include <algorithm>
#include <cmath>

namespace hilight::painter {

float brush_coverage(const BrushSettings& brush, float distance) {
  const float radius = std::max(brush.radius, 1e-12f);
  const float hard = std::clamp(brush.hardness, 0.f, 1.f) * radius;
  if (distance <= hard) return 1.f;
  if (distance >= radius) return 0.f;
  float t = (radius - distance) / (radius - hard);  // 1 at the hard core, 0 at the rim
  return t * t * (3.f - 2.f * t);
}

size_t apply_dab(const Document& document, PaintState& state, const BrushSettings& brush, BrushMode mode,
                 const SurfacePick& centre, const Visibility* visible) {
  const Scene& scene = document.scene();
  size_t touched = 0;
  for (const auto& [v, distance] : vertices_in_dab(scene, centre, brush.radius)) {
    if (visible && !visible->vertex(v)) continue;
    const float a = brush_coverage(brush, distance);
    if (!(a > 0.f)) continue;
    ++touched;
    float& w = state.weight[v];
    if (mode == BrushMode::Erase) {
      w *= 1.f - a;
      if (w < 1e-3f) w = 0.f;
      continue;
    }
    // A "don't care" vertex has no colour to blend from.
    const Rgb value = document.painted_target(brush.value(), brush.meaning, v);
    state.psi[v] = w > 0.f ? state.psi[v] + a * (value - state.psi[v]) : value;
    w = std::max(w, a);
  }
  return touched;
}

Stroke::Stroke(Document& document, const BrushSettings& brush, BrushMode mode, const Visibility* visible)
    : m_document(document), m_brush(brush), m_mode(mode), m_visible(visible) {
  m_document.begin_edit();
}

Stroke::~Stroke() { finish(); }

void Stroke::dab(const SurfacePick& centre) {
  if (!m_open) return;
  if (apply_dab(m_document, m_document.begin_edit(), m_brush, m_mode, centre, m_visible)) m_document.bump();
  m_points.push_back(centre.position);
  m_normals.push_back(centre.normal);
  m_last = centre;
}

bool Stroke::dab_at(const Vec3& world) {
  auto pick = pick_near(m_document.rays(), world);
  if (!pick) return false;
  dab(*pick);
  return true;
}

void Stroke::drag_to(const SurfacePick& centre) {
  if (!m_last) {
    dab(centre);
    return;
  }
  const SurfacePick from = *m_last;
  const float spacing = std::max(0.25f * m_brush.radius, 1e-6f);
  const int steps = std::min(1000, int(glm::length(centre.position - from.position) / spacing));
  for (int i = 1; i <= steps; ++i) {
    // Between two picks the straight line may leave the surface (a drag from
    // the floor onto a table top): each fill-in dab snaps onto the nearest
    // surface as a replay would, and one with no surface near is left out,
    // so a recorded stroke always replays.
    float t = float(i) / float(steps + 1);
    if (auto snapped = pick_near(m_document.rays(), glm::mix(from.position, centre.position, t), m_visible)) dab(*snapped);
  }
  dab(centre);
}

void Stroke::finish() {
  if (!m_open) return;
  m_open = false;
  m_document.commit_edit(m_mode == BrushMode::Erase ? "erase" : "paint");
}

void paint_stroke(Document& document, const BrushSettings& brush, BrushMode mode, const std::vector<Vec3>& world_points) {
  Stroke stroke(document, brush, mode);
  for (const Vec3& p : world_points) stroke.dab_at(p);
  stroke.finish();
}

void paint_stroke(Document& document, const BrushSettings& brush, BrushMode mode, const std::vector<SurfacePick>& picks,
                  const Visibility* visible) {
  Stroke stroke(document, brush, mode, visible);
  for (const SurfacePick& p : picks) stroke.dab(p);
  stroke.finish();
}

namespace {
float clamp_to(float v, float lo, float hi) { return std::isnan(v) ? lo : std::clamp(v, lo, hi); }
} // namespace

BrushSettings clamped_brush(BrushSettings brush, float diagonal) {
  const float d = diagonal > 0.f && std::isfinite(diagonal) ? diagonal : 1.f;
  brush.radius = clamp_to(brush.radius, 1e-4f * d, 10.f * d);
  for (float* c : {&brush.colour.r, &brush.colour.g, &brush.colour.b}) *c = clamp_to(*c, 0.f, 1e6f);
  brush.brightness = clamp_to(brush.brightness, 0.f, 1e6f);
  brush.hardness = clamp_to(brush.hardness, 0.f, 1.f);
  return brush;
}

} // namespace hilight::painter
