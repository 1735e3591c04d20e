#include "hilight/error.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/target.hpp"
#include "hilight/scene_origin.hpp"
#include "hilight/io/gltf.hpp"

#include <cmath>

namespace hilight {

namespace {
double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}
} // namespace

Target read_target(const std::filesystem::path& path, const Scene& scene, const RayScene& rays) {
  const std::string file = path.string();
  if (is_gltf_path(path)) {  // vertex colours (COLOR_0) as the target
    GltfColours colours = read_gltf_colours(path);
    for (auto& p : colours.positions) p = to_local(p, scene.frame);
    return bind_target(file, colours.positions, colours.values, colours.weights, scene, rays, colours.normals);
  }
  PlyVertices ply = read_ply_vertices(path);
  for (const char* name : {"x", "y", "z", "red", "green", "blue"})
    if (!ply.has(name)) throw InputError(file, std::string("the vertex element has no '") + name + "' property");
  const std::string color_type = ply.types["red"];
  const bool srgb = color_type == "uchar" || color_type == "uint8";
  if (!srgb && color_type != "float" && color_type != "float32" && color_type != "double" && color_type != "float64")
    throw InputError(file, "colours must be float (linear) or uchar (sRGB), not " + color_type);
  std::vector<Vec3> positions(ply.count);
  std::vector<Rgb> values(ply.count);
  std::vector<float> weights(ply.count, 1.f);
  const auto &x = ply.properties["x"], &y = ply.properties["y"], &z = ply.properties["z"];
  const auto &r = ply.properties["red"], &g = ply.properties["green"], &b = ply.properties["blue"];
  for (size_t i = 0; i < ply.count; ++i) {
    positions[i] = Vec3((glm::dvec3(x[i], y[i], z[i]) - scene.frame.origin) * scene.frame.scale);  // world → local (scene_origin.hpp)
    values[i] = srgb ? Rgb(float(srgb_decode(r[i] / 255.0)), float(srgb_decode(g[i] / 255.0)), float(srgb_decode(b[i] / 255.0)))
                     : Rgb(float(r[i]), float(g[i]), float(b[i]));
  }
  if (ply.has("weight")) {
    const auto& w = ply.properties["weight"];
    for (size_t i = 0; i < ply.count; ++i) weights[i] = float(w[i]);
  }
  std::vector<Vec3> normals;
  if (ply.has("nx") && ply.has("ny") && ply.has("nz")) {
    const auto &nx = ply.properties["nx"], &ny = ply.properties["ny"], &nz = ply.properties["nz"];
    for (size_t i = 0; i < ply.count; ++i) {
      Vec3 n(float(nx[i]), float(ny[i]), float(nz[i]));
      normals.push_back(is_finite(n) ? n : Vec3(0.f));
    }
  }
  return bind_target(file, positions, values, weights, scene, rays, normals);
}

} // namespace hilight
