#include "core/paint_meaning.hpp"

#include "hilight/units.hpp"

namespace hilight::painter {

const char* to_string(PaintMeaning meaning) { return meaning == PaintMeaning::Reflected ? "reflected" : "lamp"; }

std::optional<PaintMeaning> paint_meaning_from_string(const std::string& name) {
  if (name == "lamp") return PaintMeaning::LampColour;
  if (name == "reflected") return PaintMeaning::Reflected;
  return std::nullopt;
}

Rgb painted_radiance(const Rgb& paint, const Rgb& albedo, PaintMeaning meaning) {
  if (meaning == PaintMeaning::Reflected) return paint;
  const Rgb reflected = paint * albedo;
  const double wanted = luminance(paint), got = luminance(reflected);
  // Below a millionth of the paint's luminance the surface's chroma says nothing.
  if (!(got > 1e-6 * wanted)) return paint;
  return reflected * float(wanted / got);
}

} // namespace hilight::painter
