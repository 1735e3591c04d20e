#include "hilight/target.hpp"

#include "hilight/error.hpp"
#include "hilight/vertex_binding.hpp"

#include <cmath>
#include <tbb/parallel_for.h>

namespace hilight {

double Target::norm() const {
  double sum = 0;
  for (size_t i = 0; i < value.size(); ++i) sum += weight[i] * glm::dot(DVec3(value[i]), DVec3(value[i]));
  return std::sqrt(sum);
}

std::vector<SurfaceBinding> vertex_triangles(const Scene& scene) {
  // Per vertex, the triangle using it whose plane agrees best with its
  // normal, with the barycentrics of that corner.
  std::vector<SurfaceBinding> out(scene.positions.size());
  std::vector<float> agreement(scene.positions.size(), -3.f);
  for (uint32_t t = 0; t < scene.triangles.size(); ++t) {
    const Vec3 face = scene.face_normal(t);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = scene.triangles[t][k];
      const float a = glm::dot(face, scene.normals[v]);
      if (a > agreement[v]) {
        agreement[v] = a;
        out[v] = {t, k == 1 ? 1.f : 0.f, k == 2 ? 1.f : 0.f};
      }
    }
  }
  return out;
}

void surface_point_at(const Scene& scene, const SurfaceBinding& b, Vec3& position, Vec3& normal, Rgb& albedo) {
  const auto& tri = scene.triangles[b.triangle];
  float w = 1.f - b.u - b.v;
  position = w * scene.positions[tri[0]] + b.u * scene.positions[tri[1]] + b.v * scene.positions[tri[2]];
  Vec3 n = w * scene.normals[tri[0]] + b.u * scene.normals[tri[1]] + b.v * scene.normals[tri[2]];
  float len = glm::length(n);
  normal = len > 0.f ? n / len : scene.face_normal(b.triangle);
  albedo = scene.triangle_albedo(b.triangle);
}

Target bind_target(const std::string& source, const std::vector<Vec3>& positions, const std::vector<Rgb>& values,
                   const std::vector<float>& weights, const Scene& scene, const RayScene& rays,
                   const std::vector<Vec3>& normals) {
  const size_t n = positions.size();
  if (n == 0) throw InputError(source, "the target has no points");
  size_t bad_position = 0, bad_value = 0, negative = 0, bad_weight = 0, huge = 0;
  for (size_t i = 0; i < n; ++i) {
    bad_position += !is_finite(positions[i]);
    bad_value += !is_finite(values[i]);
    negative += is_finite(values[i]) && glm::any(glm::lessThan(values[i], Rgb(0.f)));
    huge += is_finite(values[i]) && glm::any(glm::greaterThan(values[i], Rgb(kLargestTargetValue)));
    bad_weight += !(std::isfinite(weights[i]) && weights[i] >= 0.f);
  }
  auto count_of = [&](size_t k) { return std::to_string(k) + " of " + std::to_string(n) + " points"; };
  if (bad_position) throw InputError(source, count_of(bad_position) + " have NaN or infinite coordinates");
  if (bad_value) throw InputError(source, count_of(bad_value) + " have NaN or infinite colours");
  if (negative) throw InputError(source, count_of(negative) + " have negative colours");
  if (huge) throw InputError(source, count_of(huge) + " have colours above 1e12, beyond any real light (values near float's limit overflow the solve)");
  if (bad_weight) throw InputError(source, count_of(bad_weight) + " have a negative or non-finite weight");

  const std::vector<int32_t> vertex = match_vertices(scene, positions, normals);
  const float tolerance = kTargetSurfaceTolerance * scene.diagonal();
  std::vector<Hit> hits(n);
  // Ties within a float's rounding at the scene's size, not the ray epsilon:
  // a refined render's vertex lies on its own surface, and a second sheet a
  // hair away (the Wuson's doubled mid-plane, 4e-6 of the diagonal) must not
  // win it by a better-agreeing normal.
  const float tie = 1e-7f * scene.diagonal();
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    if (vertex[i] < 0) hits[i] = rays.closest_point(positions[i], tolerance, normals.empty() ? Vec3(0.f) : normals[i], tie);
  });
  size_t off = 0;
  for (size_t i = 0; i < n; ++i) off += vertex[i] < 0 && !hits[i].valid();
  if (off)
    throw InputError(source, count_of(off) + " are farther than " + std::to_string(tolerance) +
                                 " (diagonal x " + std::to_string(kTargetSurfaceTolerance) + ") from the scene's surface");

  const std::vector<SurfaceBinding> corner = vertex_triangles(scene);
  const std::vector<Rgb> vertex_albedo = scene.vertex_albedo();
  Target t;
  t.source = source;
  for (size_t i = 0; i < n; ++i) {
    if (weights[i] == 0.f) continue;  // "don't care"
    if (const int32_t v = vertex[i]; v >= 0) {
      // Exactly what `render` shades for this vertex, bit for bit: the same
      // position and normal also key the renderers' random streams.
      t.points.positions.push_back(scene.positions[size_t(v)]);
      t.points.normals.push_back(scene.normals[size_t(v)]);
      t.points.albedo.push_back(vertex_albedo[size_t(v)]);
      t.binding.push_back(corner[size_t(v)]);
    } else {
      SurfaceBinding b{hits[i].triangle, hits[i].u, hits[i].v};
      Vec3 p, nrm;
      Rgb albedo;
      surface_point_at(scene, b, p, nrm, albedo);
      // A point on the surface that brings its own normal (a vertex of a
      // refined render: `render --refine-shadows`) is that very point, bit
      // for bit, as render shaded it: the same position and normal also key
      // the renderers' random streams. Its normal may stray from the one
      // interpolated here (a midpoint of midpoints is normalized at each
      // step: 28° where an edge's normals nearly oppose), but not by 35° or
      // more: a mesh painted in Blender brings its vertex normals averaged
      // over a box's hard edge (45°, 55° at a corner), where the scene has
      // one normal a face, and the other sheet of a doubled one is half a
      // turn off.
      const float length = normals.empty() ? 0.f : glm::length(normals[i]);
      if (hits[i].t <= rays.epsilon() && length > 0.f && glm::dot(normals[i] / length, nrm) > 0.82f) {
        p = positions[i];
        nrm = std::abs(length - 1.f) < 1e-5f ? normals[i] : normals[i] / length;
      }
      t.points.positions.push_back(p);
      t.points.normals.push_back(nrm);
      t.points.albedo.push_back(albedo);
      t.binding.push_back(b);
    }
    t.vertex.push_back(vertex[i]);
    t.value.push_back(values[i]);
    t.weight.push_back(weights[i]);
  }
  if (t.value.empty()) throw InputError(source, "every point has weight 0: nothing to match");
  if (!(t.norm() > 0.0)) throw InputError(source, "the target is black everywhere: no light can be found for it");
  return t;
}

void target_per_vertex(const Target& target, size_t vertex_count, std::vector<Rgb>& values, std::vector<float>& weights) {
  values.assign(vertex_count, Rgb(0.f));
  weights.assign(vertex_count, 0.f);
  for (size_t i = 0; i < target.size(); ++i)
    if (target.vertex[i] >= 0 && size_t(target.vertex[i]) < vertex_count) {
      values[size_t(target.vertex[i])] = target.value[i];
      weights[size_t(target.vertex[i])] = target.weight[i];
    }
}

} // namespace hilight
