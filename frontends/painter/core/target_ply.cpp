#include "core/target_ply.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/scene_origin.hpp"

#include <bit>
#include <fstream>

namespace hilight::painter {

void write_target_ply(const std::filesystem::path& path, const TargetPoints& points, const SceneFrame& frame) {
  static_assert(std::endian::native == std::endian::little, "the target PLY is written as binary_little_endian");
  const size_t n = points.positions.size();
  write_atomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment hilight painter target: linear radiance, weight 0 = don't care\n"
        << "element vertex " << n << "\n";
    // The world's coordinates: doubles when the scene was moved home (scene_origin.hpp).
    const bool far = !frame.identity();
    for (const char* name : {"x", "y", "z"}) out << (far ? "property double " : "property float ") << name << "\n";
    for (const char* name : {"nx", "ny", "nz", "red", "green", "blue", "weight"}) out << "property float " << name << "\n";
    out << "end_header\n";
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec3 world = to_world(points.positions[i], frame);
      if (far) {
        const double xyz[3] = {world.x, world.y, world.z};
        out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
      } else {
        const float xyz[3] = {points.positions[i].x, points.positions[i].y, points.positions[i].z};
        out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
      }
      const float row[7] = {points.normals[i].x, points.normals[i].y, points.normals[i].z, points.values[i].r,
                            points.values[i].g,  points.values[i].b,  points.weights[i]};
      out.write(reinterpret_cast<const char*>(row), sizeof(row));
    }
  });
}

} // namespace hilight::painter
