#include "hilight/units.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

Units parse_units(const std::string& name) {
  if (name == "radiometric") return Units::Radiometric;
  if (name == "photometric") return Units::Photometric;
  throw InputError("--units must be radiometric or photometric, not '" + name + "'");
}

const char* units_name(Units units) { return units == Units::Photometric ? "photometric" : "radiometric"; }

const char* target_quantity_name(TargetQuantity quantity) {
  return quantity == TargetQuantity::Illuminance ? "illuminance" : "luminance";
}

TargetQuantity parse_target_quantity(const std::string& name) {
  if (name == "radiance" || name == "luminance") return TargetQuantity::Radiance;
  if (name == "illuminance") return TargetQuantity::Illuminance;
  throw InputError("--target-quantity must be luminance (radiance) or illuminance, not '" + name + "'");
}

namespace {

Lighting scaled(Lighting lights, float factor) {
  for (auto& l : lights) l.intensity *= factor;
  return lights;
}

float factor(Units units) { return units == Units::Photometric ? float(kLumensPerWatt) : 1.f; }

} // namespace

Lighting lights_from_units(Lighting lights, Units units) { return scaled(std::move(lights), 1.f / factor(units)); }
Lighting lights_to_units(Lighting lights, Units units) { return scaled(std::move(lights), factor(units)); }

std::vector<Rgb> radiance_to_units(std::vector<Rgb> values, Units units) {
  for (auto& v : values) v *= factor(units);
  return values;
}

void target_from_units(Target& target, Units units, TargetQuantity quantity) {
  if (quantity == TargetQuantity::Illuminance && units != Units::Photometric)
    throw InputError(target.source, "an illuminance target is in lux: it needs --units photometric");
  for (size_t i = 0; i < target.size(); ++i) {
    Rgb& v = target.value[i];
    v /= factor(units);
    // L = ρ/π · E per channel: lux on a surface is what the surface receives.
    if (quantity == TargetQuantity::Illuminance) v *= target.points.albedo[i] / float(kPi);
  }
}

double luminaire_dimming(const Light& light) {
  if ((light.type != LightType::Luminaire && !is_area(light.type)) || !light.profile || !(light.profile->peak() > 0)) return 0.0;
  const double largest = std::max({light.intensity.r, light.intensity.g, light.intensity.b});
  return largest * kLumensPerWatt / light.profile->peak();
}

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

double luminous_flux(const Light& light) {
  if (light.type == LightType::Luminaire || (is_area(light.type) && light.profile)) {  // its profile's flux, scaled from peak candela to the light's
    if (!light.profile || !(light.profile->peak() > 0)) return 0.0;
    return kLumensPerWatt * luminance(light.intensity) * light.profile->flux() / light.profile->peak();
  }
  double solid_angle = 4.0 * kPi;
  if (is_area(light.type)) solid_angle = kPi;  // Lambertian: ∫ cos θ over the front hemisphere
  if (light.type == LightType::Spot) {
    const SpotCone cone = SpotCone::of(light);
    // ∫ over the sphere of the cone's factor: full inside the core, the
    // smoothstep edge integrates to half its band of cosines.
    solid_angle = 2.0 * kPi * ((1.0 - double(cone.cos_inner)) + 0.5 * double(cone.cos_inner - cone.cos_cutoff));
  }
  return kLumensPerWatt * luminance(light.intensity) * solid_angle;
}

} // namespace hilight
