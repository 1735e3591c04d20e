#include "core/target_ply.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"

#include <bit>
#include <fstream>

namespace hilight::painter {

void write_target_ply(const std::filesystem::path& path, const TargetPoints& points) {
  static_assert(std::endian::native == std::endian::little, "the target PLY is written as binary_little_endian");
  const size_t n = points.positions.size();
  write_atomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\ncomment hilight painter target: linear radiance, weight 0 = don't care\n"
        << "element vertex " << n << "\n";
    for (const char* name : {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "weight"})
      out << "property float " << name << "\n";
    out << "end_header\n";
    for (size_t i = 0; i < n; ++i) {
      const float row[10] = {points.positions[i].x, points.positions[i].y, points.positions[i].z,
                             points.normals[i].x,   points.normals[i].y,   points.normals[i].z,
                             points.values[i].r,    points.values[i].g,    points.values[i].b,
                             points.weights[i]};
      out.write(reinterpret_cast<const char*>(row), sizeof(row));
    }
    if (!out) throw InputError(path.string(), "write failed");
  });
}

} // namespace hilight::painter
