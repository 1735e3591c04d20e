#include "hilight/lighting.hpp"

#include <algorithm>
#include <cmath>
#include <string>


namespace hilight {

const char* to_string(LightType type) {
  switch (type) {
  case LightType::Spot: return "spot";
  case LightType::Luminaire: return "luminaire";
  case LightType::Rectangle: return "rectangle";
  case LightType::Disk: return "disk";
  case LightType::Line: return "line";
  default: return "point";
  }
}

bool light_type_from_string(const std::string& name, LightType& type) {
  for (LightType t : {LightType::Point, LightType::Spot, LightType::Luminaire, LightType::Rectangle, LightType::Disk, LightType::Line})
    if (name == to_string(t)) {
      type = t;
      return true;
    }
  return false;
}

Light Light::area(LightType type, const Vec3& position, const Vec3& direction, const Vec3& up, glm::vec2 size,
                  const Rgb& intensity) {
  Light l;
  l.type = type;
  l.position = position;
  l.direction = glm::normalize(direction);
  l.up = glm::normalize(up - glm::dot(up, l.direction) * l.direction);
  l.size = size;
  l.intensity = intensity;
  return l;
}

AreaFrame AreaFrame::of(const Light& light) {
  AreaFrame f;
  f.centre = light.position;
  f.normal = glm::normalize(light.direction);
  const Vec3 u = glm::normalize(light.up - glm::dot(light.up, f.normal) * f.normal), v = glm::cross(f.normal, u);
  if (light.type == LightType::Disk) {
    f.half_u = 0.5f * light.size[0] * u;
    f.half_v = 0.5f * light.size[0] * v;
  } else {
    f.half_u = 0.5f * light.size[0] * u;
    f.half_v = light.type == LightType::Rectangle ? 0.5f * light.size[1] * v : Vec3(0.f);
  }
  return f;
}

std::string area_light_problem(const Light& light) {
  if (!is_area(light.type)) return "";
  const int sizes = light.type == LightType::Rectangle ? 2 : 1;
  for (int i = 0; i < sizes; ++i)
    if (!(std::isfinite(light.size[i]) && light.size[i] > 0.f)) return "\"size\" must be positive and finite";
  const float len = glm::length(light.direction);
  if (!std::isfinite(len) || std::abs(len - 1.f) > 1e-3f) return "\"direction\" must be a unit vector";
  const float up = glm::length(light.up);
  if (!std::isfinite(up) || !(up > 0.f)) return "\"up\" must be a nonzero vector";
  if (glm::length(glm::cross(light.up / up, light.direction)) < 1e-3f) return "\"up\" must not be parallel to \"direction\"";
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(light.position[i]) || !std::isfinite(light.intensity[i])) return "position or intensity not finite";
  return "";
}

std::shared_ptr<const Photometry> lambertian_profile() {
  static const std::shared_ptr<const Photometry> profile = [] {
    auto p = std::make_shared<Photometry>();
    p->source = "(Lambertian)";
    p->symmetry = Photometry::Symmetry::Rotational;
    p->horizontal = {0.0};
    for (int g = 0; g <= 90; ++g) {
      p->vertical.push_back(double(g));
      p->candela.push_back(g == 90 ? 0.0 : std::cos(g * kPi / 180.0));
    }
    return std::shared_ptr<const Photometry>(std::move(p));
  }();
  return profile;
}

std::vector<Vec3> area_element_centres(const Light& light, int count) {
  if (!is_area(light.type)) return {light.position};
  const AreaFrame f = AreaFrame::of(light);
  std::vector<Vec3> centres;
  count = std::max(count, 1);
  if (light.type == LightType::Line) {
    for (int i = 0; i < count; ++i) centres.push_back(f.centre + (2.f * (float(i) + 0.5f) / float(count) - 1.f) * f.half_u);
  } else if (light.type == LightType::Rectangle) {
    const float w = light.size[0], h = light.size[1];
    const int nu = std::clamp(int(std::lround(std::sqrt(double(count) * w / h))), 1, count);
    const int nv = std::max(1, count / nu);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
        centres.push_back(f.centre + (2.f * (float(i) + 0.5f) / float(nu) - 1.f) * f.half_u +
                          (2.f * (float(j) + 0.5f) / float(nv) - 1.f) * f.half_v);
  } else {
    // Equal-area rings of equal sectors, each part at its ring's mid-area
    // radius, alternate rings turned half a sector.
    const int rings = std::max(1, int(std::lround(std::sqrt(double(count)) / 2.0))), sectors = std::max(1, count / rings);
    for (int r = 0; r < rings; ++r) {
      const float radius = std::sqrt((float(r) + 0.5f) / float(rings));
      for (int k = 0; k < sectors; ++k) {
        const float a = float(2.0 * kPi) * (float(k) + 0.5f * float(r % 2)) / float(sectors);
        centres.push_back(f.centre + radius * (std::cos(a) * f.half_u + std::sin(a) * f.half_v));
      }
    }
  }
  return centres;
}

Lighting area_light_elements(const Light& light, int count) {
  if (!is_area(light.type)) return {light};
  const std::vector<Vec3> centres = area_element_centres(light, count);
  Lighting out;
  const LuminaireFrame frame = LuminaireFrame::of(light);
  for (const Vec3& c : centres) {
    Light e;
    e.type = LightType::Luminaire;
    e.position = c;
    e.direction = frame.nadir;
    e.profile = light.profile ? light.profile : lambertian_profile();
    e.profile_path = light.profile ? light.profile_path : std::string();
    e.intensity = light.intensity / float(centres.size());
    // The element's C = 0 plane where the light's is (LuminaireFrame::of turns from its reference).
    Light reference = e;
    reference.spin_deg = 0.f;
    const LuminaireFrame rf = LuminaireFrame::of(reference);
    e.spin_deg = float(std::atan2(double(glm::dot(frame.c0, rf.c90)), double(glm::dot(frame.c0, rf.c0))) * 180.0 / kPi);
    out.push_back(e);
  }
  return out;
}

bool with_luminous_opening(Light& luminaire) {
  if (!luminaire.profile) return false;
  const Photometry& p = *luminaire.profile;
  const float length = float(p.opening_length), width = float(p.opening_width);
  if (!(length > 0.f) && !(width > 0.f)) return false;
  const LuminaireFrame frame = LuminaireFrame::of(luminaire);
  Light out = luminaire;
  out.spin_deg = 0.f;
  out.direction = frame.nadir;
  out.up = frame.c0;
  if (p.opening_round) {
    out.type = LightType::Disk;
    out.size = {std::max(length, width), 0.f};
  } else if (length > 0.f && width > 0.f) {
    out.type = LightType::Rectangle;
    out.size = {length, width};
  } else {
    out.type = LightType::Line;
    out.size = {std::max(length, width), 0.f};
    if (!(length > 0.f)) {  // along C90: the profile turned back a quarter
      out.up = frame.c90;
      out.spin_deg = -90.f;
    }
  }
  luminaire = std::move(out);
  return true;
}

LuminaireFrame LuminaireFrame::of(const Light& light) {
  LuminaireFrame f;
  f.nadir = glm::normalize(light.direction);
  // An area source's reference C = 0 plane is along its `up`.
  const Vec3 reference = is_area(light.type) ? light.up : std::abs(f.nadir.x) > 0.9f ? Vec3(0.f, 0.f, 1.f) : Vec3(1.f, 0.f, 0.f);
  Vec3 c0 = glm::normalize(reference - glm::dot(reference, f.nadir) * f.nadir);
  Vec3 c90 = glm::cross(c0, f.nadir);
  const float spin = float(light.spin_deg * kPi / 180.0);
  f.c0 = std::cos(spin) * c0 + std::sin(spin) * c90;
  f.c90 = glm::cross(f.c0, f.nadir);
  return f;
}

void LuminaireFrame::angles(const Vec3& to_point, double& c_deg, double& gamma_deg) const {
  const double down = glm::dot(to_point, nadir), x = glm::dot(to_point, c0), y = glm::dot(to_point, c90);
  gamma_deg = std::acos(std::clamp(down, -1.0, 1.0)) * 180.0 / kPi;
  c_deg = std::atan2(y, x) * 180.0 / kPi;
  if (c_deg < 0) c_deg += 360.0;
}

float luminaire_factor(const Light& light, const LuminaireFrame& frame, const Vec3& to_point) {
  if (!light.profile) return 0.f;
  const double peak = light.profile->peak();
  if (!(peak > 0)) return 0.f;
  double c, gamma;
  frame.angles(to_point, c, gamma);
  return float(light.profile->intensity(c, gamma) / peak);
}

SpotCone SpotCone::of(const Light& light) {
  SpotCone cone;
  cone.cos_cutoff = std::cos(float(light.cutoff_deg * kPi / 180.0));
  cone.cos_inner = light.falloff_deg > 0.f ? std::cos(float((light.cutoff_deg - light.falloff_deg) * kPi / 180.0)) : cone.cos_cutoff;
  return cone;
}

Lighting luminaire_as_spots(const Light& light) {
  if (is_area(light.type)) {
    Lighting out;
    for (const Light& part : area_light_elements(light, 16))
      for (const Light& spot : luminaire_as_spots(part)) out.push_back(spot);
    return out;
  }
  if (light.type != LightType::Luminaire || !light.profile || !(light.profile->peak() > 0)) return {light};
  constexpr int kBands = 18;  // every 5° to 90°, each way
  const double peak = light.profile->peak();
  const LuminaireFrame frame = LuminaireFrame::of(light);
  // The C-averaged shape at γ = 0, 5, ..., 180 (as the renderers see it).
  std::vector<double> shape(2 * kBands + 1);
  for (int j = 0; j <= 2 * kBands; ++j) {
    double sum = 0;
    for (int c = 0; c < 72; ++c) sum += light.profile->intensity(5.0 * c, 5.0 * j);
    shape[size_t(j)] = sum / 72.0 / peak;
  }
  Lighting out;
  const Photometry& p = *light.profile;
  const double gamma_max = p.type == Photometry::Type::C ? p.vertical.back() : 180.0;
  if (p.type == Photometry::Type::C && p.vertical.front() <= 0.0 && gamma_max <= 90.0) {
    // A downlight: dark beyond its last measured γ, sharply (a smooth band
    // there would light the walls above the lamp). Steps between samples
    // inside, then one hard-edged spot carrying the value at γ_max.
    auto at = [&](double gamma) {
      double sum = 0;
      for (int c = 0; c < 72; ++c) sum += p.intensity(5.0 * c, std::min(gamma, gamma_max - 1e-6));
      return sum / 72.0 / peak;
    };
    const int bands = int(std::floor(gamma_max / 5.0 + 1e-9));
    for (int k = 1; k <= bands; ++k)
      if (const double step = at(5.0 * (k - 1)) - at(5.0 * k); step != 0.0)
        out.push_back(Light::spot(light.position, frame.nadir, 5.f * float(k), light.intensity * float(step), 5.f));
    // Between the last sample and γ_max (when γ_max is not on the 5° grid).
    if (const double rest = at(5.0 * bands) - at(gamma_max); rest != 0.0 && gamma_max > 5.0 * bands)
      out.push_back(Light::spot(light.position, frame.nadir, float(gamma_max), light.intensity * float(rest),
                                float(gamma_max - 5.0 * bands)));
    if (const double edge = at(gamma_max); edge != 0.0)
      out.push_back(Light::spot(light.position, frame.nadir, float(gamma_max), light.intensity * float(edge), 0.25f));
    return out;
  }
  if (shape[size_t(kBands)] != 0.0) out.push_back(Light::point(light.position, light.intensity * float(shape[size_t(kBands)])));
  for (int k = 1; k <= kBands; ++k) {
    // Downward: the step between γ = 5(k−1) and 5k; upward: between 180 − 5(k−1) and 180 − 5k.
    const double down = shape[size_t(k - 1)] - shape[size_t(k)];
    const double up = shape[size_t(2 * kBands - k + 1)] - shape[size_t(2 * kBands - k)];
    const float cutoff = 5.f * float(k), falloff = 5.f;
    if (down != 0.0) out.push_back(Light::spot(light.position, frame.nadir, cutoff, light.intensity * float(down), falloff));
    if (up != 0.0) out.push_back(Light::spot(light.position, -frame.nadir, cutoff, light.intensity * float(up), falloff));
  }
  return out;
}

} // namespace hilight
