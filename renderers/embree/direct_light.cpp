#include "direct_light.hpp"

namespace hilight::embree {

PreparedLight::PreparedLight(const Light& light) : position(light.position), intensity(light.intensity) {
  if (light.type == LightType::Spot) {
    spot = true;
    direction = glm::normalize(light.direction);
    cone = SpotCone::of(light);
  }
  if (light.type == LightType::Luminaire) {
    luminaire = &light;
    frame = LuminaireFrame::of(light);
  }
}

} // namespace hilight::embree
