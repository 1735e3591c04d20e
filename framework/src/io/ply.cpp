#include "hilight/io/ply.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/scene.hpp"
#include "hilight/scene_origin.hpp"

#include <bit>
#include <fstream>

namespace hilight {

static_assert(std::endian::native == std::endian::little, "PLY writer assumes a little-endian host");

void write_illuminated_ply(const std::filesystem::path& path, const Scene& scene, const std::vector<Rgb>& radiance) {
  if (radiance.size() != scene.positions.size()) throw std::logic_error("write_illuminated_ply: one colour per vertex expected");
  write_atomically(path, [&](std::ostream& out) {
    // Far from the origin the world positions need doubles (scene_origin.hpp).
    const bool far = !scene.frame.identity();
    out << "ply\nformat binary_little_endian 1.0\ncomment hilight illuminated scene: linear outgoing radiance\n"
        << "element vertex " << scene.positions.size() << "\n"
        << (far ? "property double x\nproperty double y\nproperty double z\n" : "property float x\nproperty float y\nproperty float z\n")
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << "property float red\nproperty float green\nproperty float blue\n"
        << "element face " << scene.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (size_t i = 0; i < scene.positions.size(); ++i) {
      const Vec3 &p = scene.positions[i], &n = scene.normals[i];
      const Rgb& c = radiance[i];
      if (far) {
        const glm::dvec3 world = to_world(p, scene.frame);
        const double xyz[3] = {world.x, world.y, world.z};
        out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
      } else {
        const float xyz[3] = {p.x, p.y, p.z};
        out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
      }
      const float values[6] = {n.x, n.y, n.z, c.r, c.g, c.b};
      out.write(reinterpret_cast<const char*>(values), sizeof(values));
    }
    for (const auto& t : scene.triangles) {
      unsigned char count = 3;
      int32_t idx[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
      out.write(reinterpret_cast<const char*>(&count), 1);
      out.write(reinterpret_cast<const char*>(idx), sizeof(idx));
    }
  });
}

} // namespace hilight
