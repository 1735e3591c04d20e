#include "hilight/scene.hpp"

#include "hilight/enclosing_ball.hpp"

#include <algorithm>
#include <cmath>

namespace hilight {

std::vector<Rgb> Scene::vertex_albedo() const {
  std::vector<Rgb> albedo(positions.size(), Rgb(0.8f));
  std::vector<char> set(positions.size(), 0);
  for (size_t t = 0; t < triangles.size(); ++t)
    for (uint32_t v : triangles[t])
      if (!set[v]) {
        albedo[v] = triangle_albedo(t);
        set[v] = 1;
      }
  return albedo;
}

Vec3 Scene::face_normal(size_t t) const {
  const auto& tri = triangles[t];
  Vec3 n = glm::cross(positions[tri[1]] - positions[tri[0]], positions[tri[2]] - positions[tri[0]]);
  float len = glm::length(n);
  return len > 0.f ? n / len : Vec3(0.f, 0.f, 1.f);
}


void Scene::for_each_surface_point(float spacing, const std::function<void(const Vec3&)>& visit) const {
  for (const auto& tri : triangles) {
    const Vec3 &p0 = positions[tri[0]], &p1 = positions[tri[1]], &p2 = positions[tri[2]];
    const float longest = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    const int steps = std::clamp(int(std::ceil(longest / std::max(spacing, 1e-30f))), 1, 256);
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) visit(p0 + (float(i) / steps) * (p1 - p0) + (float(j) / steps) * (p2 - p0));
  }
}

void Scene::update_bounds() {
  bounds = Bounds{};
  for (const auto& p : positions) bounds.extend(p);
  const Ball ball = smallest_enclosing_ball(positions);
  size = ball.radius > 0.0 ? float(2.0 * ball.radius) : 0.f;
}

} // namespace hilight
