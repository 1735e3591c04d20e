#pragma once
/// What the brush's colour means (docs/painter.md, "What paint means").
///
/// Lamp colour (the default): the paint is the colour of the lamp and the
/// brightness the surface should show. A surface of albedo ρ lit by a lamp
/// of colour c reflects c ⊙ ρ; the target takes that chroma at the paint's
/// luminance: Ψ = (c ⊙ ρ) · Y(c) / Y(c ⊙ ρ), Y the Rec. 709 luminance. White
/// paint on a warm floor asks for a white lamp, and the floor looks warm.
/// On a grey surface Ψ is the paint itself.
///
/// Reflected: the paint is the reflected radiance Ψ itself (what the camera
/// should see), as a target file holds it: white on a warm floor asks for a
/// bluish lamp.
#include "hilight/math.hpp"

#include <optional>
#include <string>

namespace hilight::painter {

enum class PaintMeaning { LampColour, Reflected };

/// "lamp" or "reflected" (the brush action's "meaning").
const char* to_string(PaintMeaning meaning);
/// nullopt for an unknown name.
std::optional<PaintMeaning> paint_meaning_from_string(const std::string& name);

/// The target radiance Ψ that `paint` (colour × brightness) asks of a surface
/// of albedo `albedo`. A surface that reflects none of the lamp's colour
/// (black, or a pure blue lamp on a red surface) takes the paint as it is.
Rgb painted_radiance(const Rgb& paint, const Rgb& albedo, PaintMeaning meaning);

} // namespace hilight::painter
