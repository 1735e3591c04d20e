#pragma once
// The file's own precision (issue 35, item 14): Debian's assimp reads in
// single precision (ai_real is float), so a scene 10⁴ m from the origin
// would be rounded to about a millimetre (10⁶ m: 6 cm) before load_scene
// moves it home. For the text formats hilight can read itself (OBJ, ASCII
// PLY) the positions are read here in double, the origin is taken from
// their bounds, and assimp is given the file with every position already
// moved by −origin: what it rounds is small. Internal to scene_io.cpp.
#include "hilight/math.hpp"
#include "hilight/scene.hpp"
#include "hilight/scene_origin.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace hilight::far_positions {

/// How a file's positions are held, for what assimp's floats lose.
enum class Precision {
  Double,  ///< read here in double (OBJ, ASCII PLY)
  Float,   ///< the file holds floats (binary PLY or STL): nothing to lose
  Rounded  ///< read by assimp in single precision from a more precise file
};

struct Shifted {
  Precision precision = Precision::Rounded;
  glm::dvec3 origin{0.0};  ///< where the scene is moved home from (0: not moved)
  std::string text;        ///< the file with every position minus origin (empty: not moved)
};

namespace detail {

inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// The tokens of one line, split at blanks.
inline std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
}

inline bool to_double(const std::string& token, double& value) {
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end && *end == '\0' && end != token.c_str() && std::isfinite(value);
}

inline std::string print(double v) {
  char text[40];
  std::snprintf(text, sizeof(text), "%.17g", v);
  return text;
}

/// A file's lines and which of their tokens are x, y, z of a vertex.
struct Layout {
  std::vector<std::string> lines;
  std::vector<size_t> vertex_lines;  ///< indices into lines
  size_t first = 0;                  ///< OBJ: token 1 is x; PLY: the x, y, z token indices below
  size_t x = 0, y = 1, z = 2;
};

/// OBJ: lines "v x y z [w] [r g b]".
inline bool obj_layout(std::istream& in, Layout& layout) {
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() > 2 && line[0] == 'v' && (line[1] == ' ' || line[1] == '\t')) layout.vertex_lines.push_back(layout.lines.size());
    layout.lines.push_back(std::move(line));
  }
  layout.x = 1, layout.y = 2, layout.z = 3;
  return true;
}

/// ASCII PLY: one line per element, elements in the header's order; the
/// vertex element's scalar properties x, y, z. False for anything else
/// (binary, lists in the vertex element): assimp reads it as it is.
inline bool ply_layout(std::istream& in, Layout& layout, Precision& precision) {
  std::string line;
  struct Element {
    std::string name;
    size_t count = 0;
  };
  std::vector<Element> elements;
  bool ascii = false, vertex_list = false;
  long x = -1, y = -1, z = -1, property = 0;
  std::string x_type;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    layout.lines.push_back(line);
    const auto t = tokens(line);
    if (t.empty()) continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format" && t.size() > 1) ascii = t[1] == "ascii";
    if (t[0] == "element" && t.size() > 2) {
      elements.push_back({t[1], size_t(std::strtoull(t[2].c_str(), nullptr, 10))});
      property = 0;
    }
    if (t[0] == "property" && !elements.empty() && elements.back().name == "vertex") {
      if (t.size() > 1 && t[1] == "list") vertex_list = true;
      const std::string& name = t.back();
      if (name == "x") x = property, x_type = t.size() > 2 ? t[1] : "";
      if (name == "y") y = property;
      if (name == "z") z = property;
      ++property;
    }
  }
  if (!ascii) {
    precision = x_type == "float" || x_type == "float32" ? Precision::Float : Precision::Rounded;
    return false;
  }
  if (vertex_list || x < 0 || y < 0 || z < 0) return false;
  layout.x = size_t(x), layout.y = size_t(y), layout.z = size_t(z);
  for (const Element& e : elements)
    for (size_t i = 0; i < e.count; ++i) {
      if (!std::getline(in, line)) return false;  // short: let assimp say what is wrong
      if (e.name == "vertex") layout.vertex_lines.push_back(layout.lines.size());
      layout.lines.push_back(std::move(line));
    }
  for (std::string rest; std::getline(in, rest);) layout.lines.push_back(std::move(rest));
  return true;
}

} // namespace detail

/// Reads a scene file's positions in double where hilight can; `text` is
/// filled when the scene is far from the origin (the file moved home).
/// Binary STL is float by its format; everything else is Rounded.
inline Shifted read(const std::filesystem::path& path) {
  using namespace detail;
  Shifted out;
  const std::string ext = lower_extension(path);
  std::error_code ec;
  if (ext == ".stl") {  // binary STL: 84 bytes of header and count, 50 a triangle
    std::ifstream in(path, std::ios::binary);
    char header[84] = {};
    uint32_t count = 0;
    if (in.read(header, 84)) std::memcpy(&count, header + 80, 4);
    if (in && std::filesystem::file_size(path, ec) == 84 + 50 * uintmax_t(count)) out.precision = Precision::Float;
    return out;
  }
  if (ext != ".obj" && ext != ".ply") return out;
  std::ifstream in(path, std::ios::binary);
  Layout layout;
  if (ext == ".obj" ? !obj_layout(in, layout) : !ply_layout(in, layout, out.precision)) return out;
  // The positions in double, and their bounds.
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (size_t k = 0; k < layout.vertex_lines.size(); ++k) {
    const auto t = tokens(layout.lines[layout.vertex_lines[k]]);  // not kept: most scenes are near home
    glm::dvec3 p;
    if (std::max({layout.x, layout.y, layout.z}) >= t.size() || !to_double(t[layout.x], p.x) || !to_double(t[layout.y], p.y) ||
        !to_double(t[layout.z], p.z))
      return out;  // not what hilight understands: assimp reads it, and says what is wrong
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  out.precision = Precision::Double;
  if (layout.vertex_lines.empty()) return out;
  Bounds bounds;
  bounds.lo = Vec3(lo), bounds.hi = Vec3(hi);
  out.origin = recentring_origin(bounds);
  if (out.origin == glm::dvec3(0.0)) return out;
  // The file again, each position minus the origin, in full.
  for (size_t k = 0; k < layout.vertex_lines.size(); ++k) {
    auto t = tokens(layout.lines[layout.vertex_lines[k]]);
    for (int axis = 0; axis < 3; ++axis) {
      const size_t i = axis == 0 ? layout.x : axis == 1 ? layout.y : layout.z;
      double v = 0;
      to_double(t[i], v);
      t[i] = print(v - out.origin[axis]);
    }
    std::string line;
    for (const auto& token : t) line += (line.empty() ? "" : " ") + token;
    layout.lines[layout.vertex_lines[k]] = std::move(line);
  }
  for (const auto& line : layout.lines) out.text += line + "\n";
  return out;
}

/// What single precision loses at `largest` (the largest coordinate), in
/// the file's unit: half a float's step there.
inline double float_rounding(double largest) {
  return largest > 0 ? std::exp2(std::floor(std::log2(largest)) - 24.0) : 0.0;
}

} // namespace hilight::far_positions
