#pragma once
/// Radiometric and photometric units (docs/rendering-model.md, "Units").
/// hilight computes in radiometric units: light intensity in W/sr and
/// surface values as outgoing radiance in W/(sr·m²), per RGB channel. In
/// photometric units (`--units photometric`) lights are in candela and
/// surface values in cd/m² (luminance), per channel, both 683 × the
/// radiometric value (683 lm/W, the luminous efficacy at 555 nm; glTF's
/// KHR_lights_punctual and Blender's importer use the same factor). A target
/// may instead give illuminance in lux on the surface: E_v = π · L_v / ρ.
/// Scalar figures (lumens, a channel-free cd) weight R, G, B by Rec. 709's
/// luminance weights 0.2126, 0.7152, 0.0722.
#include "hilight/lighting.hpp"
#include "hilight/target.hpp"

#include <string>

namespace hilight {

constexpr double kLumensPerWatt = 683.0;

enum class Units { Radiometric, Photometric };

/// "radiometric" / "photometric"; InputError otherwise.
Units parse_units(const std::string& name);
/// The name parse_units reads back.
const char* units_name(Units units);

/// Lights given in `units` → hilight's (W/sr), and back.
Lighting lights_from_units(Lighting lights, Units units);
Lighting lights_to_units(Lighting lights, Units units);

/// Surface values (radiance) → `units` (cd/m² when photometric).
std::vector<Rgb> radiance_to_units(std::vector<Rgb> values, Units units);

/// What a target's values mean.
enum class TargetQuantity {
  Radiance,     ///< hilight's own: W/(sr·m²), or cd/m² (luminance) when photometric
  Illuminance,  ///< lux on the surface (photometric only): converted with each point's albedo
};
TargetQuantity parse_target_quantity(const std::string& name);
/// The name parse_target_quantity reads back ("luminance" for radiance).
const char* target_quantity_name(TargetQuantity quantity);

/// Converts a target read in `units`/`quantity` to hilight's radiance, in place.
void target_from_units(Target& target, Units units, TargetQuantity quantity);

/// Rec. 709 luminance of an RGB triple.
double luminance(const Rgb& c);

/// Luminous flux in lumens of a light given in hilight's units: 683 ×
/// luminance(I) × the solid angle it lights (4π for a point; a spot's cone,
/// its smoothstep edge counted at its mean, one half).
double luminous_flux(const Light& light);

/// A luminaire's intensity as a share of its profile's rated peak (1 = the
/// file's rated output; the largest channel counts). 0 for other lights.
double luminaire_dimming(const Light& light);

} // namespace hilight
