#include "hilight/io/pov_export.hpp"

#include "hilight/bounces.hpp"
#include "hilight/error.hpp"

#include <cmath>
#include <iomanip>

namespace hilight {

namespace {

std::ostream& vec(std::ostream& out, const Vec3& v) { return out << '<' << v.x << ',' << v.y << ',' << v.z << '>'; }

/// POV-Ray's pixel is pigment · colour · attenuation · cos θ, with no 1/π;
/// attenuation is 2fd²/d². hilight's radiance is ρ/π · I cos θ / d², so the
/// colour that gives it is I / (π · 2 fd²).
Rgb pov_colour(const Rgb& intensity, float fd) { return intensity / float(kPi * 2.0 * double(fd) * double(fd)); }

} // namespace

float pov_fade_distance(const Scene& scene) { return 1e-4f * scene.diagonal(); }

void write_pov_scene(std::ostream& out, const Scene& scene, const Lighting& lights, const PovSettings& s) {
  out << std::setprecision(9);
  out << "// Written by hilight: follows docs/rendering-model.md (see docs/povray.md).\n#version 3.7;\n";
  out << "global_settings {\n  assumed_gamma 1.0\n  ambient_light 0\n  max_trace_level 8\n";
  if (s.bounces != 0) {
    // recursion_limit N: exactly N diffuse bounces ("all": POV-Ray's most, 20). always_sample off
    // and a dense pretrace keep the estimate smooth; brightness 1 keeps it physical.
    out << "  radiosity {\n    recursion_limit " << (s.bounces == kAllBounces ? kPovMaxBounces : s.bounces) << "\n    brightness 1\n    count " << s.radiosity_count
        << "\n    error_bound " << s.error_bound << "\n    low_error_factor 0.5\n    pretrace_start 0.08\n    pretrace_end "
        << s.pretrace_end << "\n    nearest_count 10\n    minimum_reuse 0.005\n    gray_threshold 0\n    adc_bailout 0.001\n"
        << "    always_sample off\n    normal off\n  }\n";
  }
  out << "}\nbackground { color rgb 0 }\n";
  // Camera rays that miss the scene hit this sphere and read -1; radiosity
  // rays do not see it (a -1 background would feed negative light back).
  const Vec3 c = scene.bounds.center();
  out << "sphere { ";
  vec(out, c) << ", " << 4.f * scene.diagonal()
              << " hollow texture { pigment { color rgb -1 } finish { emission 1 diffuse 0 ambient 0 } } no_shadow no_radiosity no_reflection }\n";

  const float fd = pov_fade_distance(scene);
  // POV-Ray has no measured distributions: a luminaire goes as its
  // rotational average, a point light and signed spotlights (lighting.hpp).
  Lighting expanded;
  for (const Light& l : lights)
    for (const Light& part : luminaire_as_spots(l)) expanded.push_back(part);
  for (const Light& l : expanded) {
    out << "light_source { ";
    vec(out, l.position) << " color rgb ";
    vec(out, pov_colour(l.intensity, fd)) << "\n  fade_distance " << fd << " fade_power 2";
    if (l.type == LightType::Spot) {
      // Full intensity up to radius, none beyond falloff (hilight: cutoff −
      // falloff and cutoff); tightness 0 removes POV-Ray's extra cosine power.
      out << "\n  spotlight point_at ";
      vec(out, l.position + l.direction) << " radius " << (l.cutoff_deg - l.falloff_deg) << " falloff " << l.cutoff_deg
                                         << " tightness 0";
    }
    out << " }\n";
  }

  out << "mesh2 {\n  vertex_vectors { " << scene.positions.size();
  for (const auto& p : scene.positions) vec(out << ",\n    ", p);
  out << " }\n  normal_vectors { " << scene.normals.size();
  for (const auto& n : scene.normals) vec(out << ",\n    ", n);
  out << " }\n  texture_list { " << scene.materials.size();
  for (const auto& m : scene.materials) {
    out << ",\n    texture { pigment { color rgb ";
    vec(out, m.albedo) << " } finish { diffuse 1 ambient 0 emission 0 specular 0 phong 0 } }";
  }
  out << " }\n  face_indices { " << scene.triangles.size();
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    out << ",\n    <" << tri[0] << ',' << tri[1] << ',' << tri[2] << ">, " << scene.triangle_material[t];
  }
  // Normals index like the vertices; two-sided like hilight's surfaces.
  // inside_vector makes POV-Ray report every hit along a ray: without it a
  // mesh stops at its nearest hit, and a shadow ray that first crosses the
  // point's own facets (ignored as too close) never sees a real blocker
  // behind them (docs/povray.md). Nothing here uses insideness.
  out << " }\n  inside_vector <0, 0, 1>\n" << (s.double_illuminate ? "  double_illuminate\n" : "") << "}\n";
}

void write_pov_camera(std::ostream& out, const Camera& camera, int width, int height) {
  const float aspect = float(width) / float(height);
  const double hfov = 2.0 * std::atan(std::tan(camera.fov_deg * kPi / 360.0) * aspect) * 180.0 / kPi;
  Camera::Basis b = camera.basis();
  out << std::setprecision(9) << "camera {\n  perspective\n  location ";
  vec(out, camera.eye) << "\n  sky ";
  vec(out, b.up) << "\n  up ";
  vec(out, b.up) << "\n  right ";
  vec(out, -aspect * b.right) << "  // mirrored: POV-Ray is left-handed\n  angle " << hfov << "\n  look_at ";
  vec(out, camera.target) << "\n}\n";
}

} // namespace hilight
