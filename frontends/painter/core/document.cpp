#include "core/document.hpp"

#include "core/target_ply.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/scene_origin.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"

#include <functional>
#include <stdexcept>

namespace hilight::painter {

bool PaintState::operator==(const PaintState& other) const {
  return psi == other.psi && weight == other.weight && lights == other.lights && spot_hints == other.spot_hints;
}

Document::Document(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays)
    : m_scene(std::move(scene)), m_rays(std::move(rays)), m_albedo(m_scene->vertex_albedo()) {
  m_state.psi.assign(m_scene->positions.size(), Rgb(0.f));
  m_state.weight.assign(m_scene->positions.size(), 0.f);
}

PaintState& Document::begin_edit() {
  if (!m_editing) {
    m_edit_start = m_state;
    m_editing = true;
  }
  return m_state;
}

void Document::commit_edit(const std::string& label) {
  if (!m_editing) return;
  m_editing = false;
  if (m_state == m_edit_start) return;
  m_undo.push_back({std::move(m_edit_start), label});
  m_edit_start = PaintState{};
  m_redo.clear();
  trim_history();
  ++m_revision;
}

void Document::cancel_edit() {
  if (!m_editing) return;
  m_editing = false;
  m_state = std::move(m_edit_start);
  m_edit_start = PaintState{};
  ++m_revision;
}

void Document::apply(const std::string& label, const std::function<void(PaintState&)>& edit) {
  if (m_editing) commit_edit("edit");  // an open stroke stays its own step
  PaintState& state = begin_edit();
  try {
    edit(state);
  } catch (...) {
    cancel_edit();
    throw;
  }
  commit_edit(label);
}

void Document::set_lights(const Lighting& lights, const std::string& label) {
  apply(label, [&](PaintState& s) { s.lights = lights; });
}

std::string Document::undo_label() const { return m_undo.empty() ? std::string() : m_undo.back().label; }
std::string Document::redo_label() const { return m_redo.empty() ? std::string() : m_redo.back().label; }

void Document::undo() {
  if (m_editing) commit_edit("edit");
  if (m_undo.empty()) return;
  Step step = std::move(m_undo.back());
  m_undo.pop_back();
  m_redo.push_back({std::move(m_state), step.label});
  m_state = std::move(step.before);
  ++m_revision;
}

void Document::redo() {
  if (m_editing) commit_edit("edit");
  if (m_redo.empty()) return;
  Step step = std::move(m_redo.back());
  m_redo.pop_back();
  m_undo.push_back({std::move(m_state), step.label});
  m_state = std::move(step.before);
  ++m_revision;
}

void Document::trim_history() {
  while (m_undo.size() > kHistoryLimit) m_undo.pop_front();
}

size_t Document::painted_count() const {
  size_t n = 0;
  for (float w : m_state.weight) n += w > 0.f;
  return n;
}

namespace {

TargetPoints painted_points(const Scene& scene, const PaintState& state,
                            const std::function<bool(uint32_t)>& keep = {}) {
  TargetPoints points;
  for (size_t v = 0; v < state.weight.size(); ++v) {
    if (!(state.weight[v] > 0.f) || (keep && !keep(uint32_t(v)))) continue;
    points.positions.push_back(scene.positions[v]);
    points.normals.push_back(scene.normals[v]);
    points.values.push_back(state.psi[v]);
    points.weights.push_back(state.weight[v]);
  }
  return points;
}

} // namespace

void Document::set_units(Units units, TargetQuantity quantity) {
  if (quantity == TargetQuantity::Illuminance && units != Units::Photometric)
    throw InputError("--target-quantity illuminance is in lux: it needs --units photometric");
  m_units = units;
  m_quantity = quantity;
}

Rgb Document::painted_target(const Rgb& paint, PaintMeaning meaning, size_t v) const {
  const float per_watt = m_units == Units::Photometric ? float(kLumensPerWatt) : 1.f;
  if (m_quantity == TargetQuantity::Illuminance) return m_albedo[v] * paint / (per_watt * float(kPi));
  return painted_radiance(paint, m_albedo[v], meaning) / per_watt;
}

std::vector<Rgb> Document::psi_in_file_units() const {
  // The inverse of target_from_units: cd/m² (683 lm/W), and for lux E = π L / ρ per channel.
  const float per_watt = m_units == Units::Photometric ? float(kLumensPerWatt) : 1.f;
  std::vector<Rgb> out(m_state.psi.size());
  for (size_t v = 0; v < out.size(); ++v) {
    Rgb value = m_state.psi[v] * per_watt;
    if (m_quantity == TargetQuantity::Illuminance)
      for (int c = 0; c < 3; ++c) value[c] = m_albedo[v][c] > 0.f ? value[c] * float(kPi) / m_albedo[v][c] : 0.f;
    out[v] = value;
  }
  return out;
}

Target Document::target() const { return target({}, "nothing is painted (every weight is 0)"); }

Target Document::target(const std::function<bool(uint32_t)>& keep, const std::string& if_none) const {
  TargetPoints points = painted_points(*m_scene, m_state, keep);
  if (points.positions.empty()) throw InputError("painted target", if_none);
  return bind_target("painted target", points.positions, points.values, points.weights, *m_scene, *m_rays,
                     points.normals);
}

void Document::save_target(const std::filesystem::path& path) const {
  TargetPoints points = painted_points(*m_scene, m_state);
  if (points.positions.empty()) throw InputError(path.string(), "nothing is painted: no target to save");
  for (size_t v = 0; v < m_state.psi.size(); ++v)
    if (m_state.weight[v] > 0.f && !is_finite(m_state.psi[v]))
      throw InputError(path.string(), "not written: vertex " + std::to_string(v) +
                                          " has a non-finite painted value (a brightness too large for a float)");
  const std::vector<Rgb> values = psi_in_file_units();  // as hilight solve reads them back with the same --units
  if (is_gltf_path(path)) {  // the scene with the paint as COLOR_0, alpha the weight (docs/interchange.md)
    GltfExport gltf;
    gltf.scene = m_scene.get();
    gltf.target = values;
    gltf.target_weight = m_state.weight;
    write_gltf(path, gltf);
    return;
  }
  for (size_t v = 0, k = 0; v < m_state.weight.size(); ++v)
    if (m_state.weight[v] > 0.f) points.values[k++] = values[v];
  write_target_ply(path, points, m_scene->frame);
}

void Document::load_target(const std::filesystem::path& path) {
  Target target = read_target(path, *m_scene, *m_rays);
  target_from_units(target, m_units, m_quantity);
  const size_t n = m_scene->positions.size();
  std::vector<Rgb> sum(n, Rgb(0.f));
  std::vector<float> weight_sum(n, 0.f);
  std::vector<uint32_t> hits(n, 0);
  std::vector<Rgb> first(n);  // one point per vertex (a file the painter wrote) keeps its exact value
  for (size_t i = 0; i < target.size(); ++i) {
    const SurfaceBinding& b = target.binding[i];
    const auto& tri = m_scene->triangles[b.triangle];
    const float bary[3] = {1.f - b.u - b.v, b.u, b.v};
    int nearest = bary[1] > bary[0] ? 1 : 0;
    if (bary[2] > bary[nearest]) nearest = 2;
    const uint32_t v = tri[size_t(nearest)];
    if (!hits[v]) first[v] = target.value[i];
    sum[v] += target.weight[i] * target.value[i];
    weight_sum[v] += target.weight[i];
    ++hits[v];
  }
  apply("load target " + path.filename().string(), [&](PaintState& s) {
    for (size_t v = 0; v < n; ++v) {
      s.psi[v] = hits[v] == 1 ? first[v] : weight_sum[v] > 0.f ? sum[v] / weight_sum[v] : Rgb(0.f);
      s.weight[v] = hits[v] ? weight_sum[v] / float(hits[v]) : 0.f;
    }
  });
}

void Document::save_lights(const std::filesystem::path& path) const {
  for (size_t i = 0; i < m_state.lights.size(); ++i) {
    const Light& l = m_state.lights[i];
    if (!is_finite(l.position) || !is_finite(l.intensity) || !is_finite(l.direction))
      throw InputError(path.string(), "not written: light " + std::to_string(i) +
                                          " is not finite (an intensity or position too large for a float)");
  }
  if (is_gltf_path(path)) {
    GltfExport gltf;
    gltf.scene = m_scene.get();
    gltf.lights = m_state.lights;
    write_gltf(path, gltf);
    return;
  }
  write_lights_file(path, m_state.lights, m_units, m_scene->frame);  // the world's coordinates and the unit stated in files
}

void Document::load_lights(const std::filesystem::path& path) {
  Lighting lights = read_lights_file(path, m_units, &m_scene->frame);
  set_lights(lights, "load lights " + path.filename().string());
}

} // namespace hilight::painter
