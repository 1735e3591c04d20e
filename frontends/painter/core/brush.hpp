#pragma once
/// The brush: paints Ψ and weight on scene vertices around a world-space dab.
///
/// Coverage of a vertex at distance d from the dab's centre: 1 inside
/// hardness·radius, falling to 0 at the radius by smoothstep (hardness 1: a
/// hard disc; 0: soft all the way from the centre). Painting blends Ψ toward
/// the target that colour·brightness asks of the vertex's surface (its
/// meaning: core/paint_meaning.hpp) by the coverage (a vertex that was "don't
/// care" takes it outright) and raises the weight to at least the coverage; the
/// eraser lowers the weight by the coverage, back to 0 = "don't care".
/// A stroke is a sequence of dabs and one undo step.
#include "core/document.hpp"
#include "core/paint_meaning.hpp"
#include "core/region.hpp"
#include "core/view_clip.hpp"

namespace hilight::painter {

struct BrushSettings {
  float radius = 0.25f;    ///< world units
  Rgb colour{1.f};         ///< linear RGB, usually in [0, 1]
  float brightness = 1.f;  ///< multiplies colour: Ψ = colour · brightness (radiance)
  float hardness = 0.5f;   ///< 0 soft .. 1 hard disc
  PaintMeaning meaning = PaintMeaning::LampColour;  ///< what the colour asks of the surface

  Rgb value() const { return colour * brightness; }
  bool operator==(const BrushSettings&) const = default;
};

/// `brush` inside what a brush action accepts (the UI's typed-in values):
/// radius in [1e-4, 10] × diagonal, colour and brightness in [0, 1e6],
/// hardness in [0, 1]; NaN becomes the lower bound.
BrushSettings clamped_brush(BrushSettings brush, float diagonal);

enum class BrushMode { Paint, Erase };

/// Coverage in [0, 1] of a vertex at `distance` (see above).
float brush_coverage(const BrushSettings& brush, float distance);

/// Applies one dab to `state`; returns how many vertices it touched.
/// Vertices `visible` hides (clipped by the section or cut away) get no paint.
/// `state` is `document`'s open edit; the document says what the paint
/// asks of each vertex (Document::painted_target: its albedo, the units).
size_t apply_dab(const Document& document, PaintState& state, const BrushSettings& brush, BrushMode mode,
                 const SurfacePick& centre, const Visibility* visible = nullptr);

/// One stroke = one undo step. Dabs show at once (the document's revision
/// moves); finish() commits, and so does the destructor if finish() was not
/// called. A stroke that touched nothing leaves no step.
class Stroke {
public:
  /// `visible` (if given, it must outlive the stroke): what the view shows;
  /// hidden vertices get no paint and fill-in dabs never land on hidden surfaces.
  Stroke(Document& document, const BrushSettings& brush, BrushMode mode, const Visibility* visible = nullptr);
  ~Stroke();
  Stroke(const Stroke&) = delete;
  Stroke& operator=(const Stroke&) = delete;

  /// A dab at a picked surface point.
  void dab(const SurfacePick& centre);
  /// A dab at a bare world point, snapped to the nearest surface; false if
  /// no surface is near.
  bool dab_at(const Vec3& world);
  /// Dabs along the segment from the last dab to `centre`, spaced a quarter
  /// radius apart, so fast mouse moves leave no gaps.
  void drag_to(const SurfacePick& centre);
  void finish();

  /// World positions of the dabs so far (what a session script records).
  const std::vector<Vec3>& points() const { return m_points; }
  /// The dabs' surface normals (recorded too: at a crease the nearest
  /// surface of a bare point may be the other face).
  const std::vector<Vec3>& normals() const { return m_normals; }

private:
  Document& m_document;
  BrushSettings m_brush;
  BrushMode m_mode;
  const Visibility* m_visible = nullptr;
  std::vector<Vec3> m_points, m_normals;
  std::optional<SurfacePick> m_last;
  bool m_open = true;
};

/// A whole stroke from world points (session replay): one undo step.
void paint_stroke(Document& document, const BrushSettings& brush, BrushMode mode, const std::vector<Vec3>& world_points);
/// A whole stroke from surface picks: one undo step (hidden vertices unpainted).
void paint_stroke(Document& document, const BrushSettings& brush, BrushMode mode, const std::vector<SurfacePick>& picks,
                  const Visibility* visible = nullptr);

} // namespace hilight::painter
