#include "hilight/camera.hpp"

#include "hilight/error.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace hilight {

Camera Camera::parse(const std::string& text) {
  std::vector<float> values;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    float v = std::strtof(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v))
      throw InputError("--camera: '" + item + "' is not a finite number");
    values.push_back(v);
  }
  if (values.size() != 7) throw InputError("--camera: expected 7 numbers eye_x,eye_y,eye_z,target_x,target_y,target_z,fov_deg");
  Camera cam;
  cam.eye = {values[0], values[1], values[2]};
  cam.target = {values[3], values[4], values[5]};
  cam.fov_deg = values[6];
  if (glm::length(cam.target - cam.eye) <= 0.f) throw InputError("--camera: eye and target are the same point");
  if (!(cam.fov_deg > 0.f && cam.fov_deg < 179.f)) throw InputError("--camera: fov_deg must be in (0, 179)");
  return cam;
}

Camera Camera::framing(const Bounds& bounds, float aspect) {
  Camera cam;
  cam.target = bounds.center();
  float radius = 0.5f * bounds.diagonal();
  float half_fov = float(cam.fov_deg * kPi / 360.0);
  float half_fov_min = aspect < 1.f ? std::atan(std::tan(half_fov) * aspect) : half_fov;
  float distance = radius / std::sin(half_fov_min);
  cam.eye = cam.target + distance * glm::normalize(Vec3(0.55f, 0.6f, 1.f));
  return cam;
}

Camera::Basis Camera::basis() const {
  Basis b;
  b.forward = glm::normalize(target - eye);
  Vec3 up_hint = std::abs(b.forward.y) > 0.99f ? Vec3(0.f, 0.f, -1.f) : Vec3(0.f, 1.f, 0.f);
  b.right = glm::normalize(glm::cross(b.forward, up_hint));
  b.up = glm::cross(b.right, b.forward);
  b.tan_half_fov = std::tan(float(fov_deg * kPi / 360.0));
  return b;
}

} // namespace hilight
