// glTF in: lights (KHR_lights_punctual) and coloured vertices (targets) from
// a file's default scene, node transforms applied. Every index, offset and
// size in the file is checked before it is used: a broken file is an
// InputError naming it, never a crash.
#include "hilight/error.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/scene_origin.hpp"
#include "confined_path.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <set>
#include <tuple>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

namespace hilight {

namespace fs = std::filesystem;

namespace {

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;  // textures play no part in hilight's Lambertian model
}

/// What the file callbacks know: the glTF's folder, and the first file it
/// names outside that folder (refused; the load then fails on it).
struct Referenced {
  fs::path folder;
  std::string outside;
};

/// tinygltf checks a file exists before reading it: one outside the folder
/// is said to exist, so that the read refuses it by name and nothing about
/// it (its existence, its size) reaches the error.
bool referenced_file_exists(const std::string& file, void* context) {
  const auto* referenced = static_cast<const Referenced*>(context);
  return !inside_folder(referenced->folder, file) || tinygltf::FileExists(file, nullptr);
}

/// Files a glTF refers to (buffers, images): inside its folder only (issue 35),
/// regular files of sane size only — a `uri` naming /dev/zero would
/// otherwise never finish reading.
bool read_referenced_file(std::vector<unsigned char>* out, std::string* err, const std::string& file, void* context) {
  auto* referenced = static_cast<Referenced*>(context);
  if (!inside_folder(referenced->folder, file)) {
    if (referenced->outside.empty()) referenced->outside = file;
    if (err) *err += "refers to a file outside its folder\n";
    return false;
  }
  std::error_code ec;
  if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) > (uintmax_t(1) << 31)) {
    if (err) *err += "cannot read " + file + " (not a regular file, or larger than 2 GB)\n";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    if (err) *err += "cannot open " + file + "\n";
    return false;
  }
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

tinygltf::Model load(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(path.string(), "not a regular file (or no such file)");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError(path.string(), "cannot open the file");
  char magic[4] = {};
  probe.read(magic, 4);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  Referenced referenced{path.parent_path(), {}};
  loader.SetFsCallbacks({&referenced_file_exists, &tinygltf::ExpandFilePath, &read_referenced_file, &tinygltf::WriteWholeFile, &referenced});
  tinygltf::Model model;
  std::string error, warning;
  const bool binary = std::memcmp(magic, "glTF", 4) == 0;
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                         : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
  if (!ok && !referenced.outside.empty())  // a buffer; an image outside is not read either, and not needed
    throw InputError(path.string(), "refers to " + named_from(referenced.folder, referenced.outside) +
                                        ", outside its folder (the files it names must lie in its folder or below)");
  if (!ok) {
    std::string first = error.substr(0, error.find('\n'));
    if (first.empty()) first = "not a glTF 2.0 file";
    throw InputError(path.string(), "not a readable glTF: " + first);
  }
  return model;
}

glm::dmat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)
    m *= glm::mat4_cast(glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])));
  if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

/// Calls `visit(node, world)` for every node of the default scene (or, with
/// no scenes, of every root), children after parents. A cycle is an error.
void for_each_node(const tinygltf::Model& model, const fs::path& path,
                   const std::function<void(const tinygltf::Node&, const glm::dmat4&)>& visit) {
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int s = model.defaultScene >= 0 && size_t(model.defaultScene) < model.scenes.size() ? model.defaultScene : 0;
    roots = model.scenes[size_t(s)].nodes;
  } else {
    std::vector<bool> child(model.nodes.size(), false);
    for (const auto& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (!child[i]) roots.push_back(int(i));
  }
  std::vector<bool> on_path(model.nodes.size(), false);
  std::function<void(int, const glm::dmat4&, int)> walk = [&](int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || size_t(index) >= model.nodes.size()) throw InputError(path.string(), "a node index is out of range");
    if (on_path[size_t(index)] || depth > 256) throw InputError(path.string(), "the node hierarchy has a cycle");
    on_path[size_t(index)] = true;
    const tinygltf::Node& node = model.nodes[size_t(index)];
    const glm::dmat4 world = parent * local_transform(node);
    visit(node, world);
    for (int c : node.children) walk(c, world, depth + 1);
    on_path[size_t(index)] = false;
  };
  for (int r : roots) walk(r, glm::dmat4(1.0), 0);
}

int components_of(int type) {
  switch (type) {
  case TINYGLTF_TYPE_SCALAR: return 1;
  case TINYGLTF_TYPE_VEC2: return 2;
  case TINYGLTF_TYPE_VEC3: return 3;
  case TINYGLTF_TYPE_VEC4: return 4;
  default: return 0;
  }
}

/// Accessor `index` as floats, `components` per element (normalized
/// integers mapped to [0, 1] as the spec says).
std::vector<float> read_floats(const tinygltf::Model& model, int index, const fs::path& path, const std::string& what,
                               int& components) {
  auto bad = [&](const std::string& problem) { return InputError(path.string(), what + ": " + problem); };
  if (index < 0 || size_t(index) >= model.accessors.size()) throw bad("accessor index out of range");
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.sparse.isSparse) throw bad("sparse accessors are not supported");
  components = components_of(a.type);
  if (components == 0) throw bad("unexpected accessor type");
  size_t size = 0;
  switch (a.componentType) {
  case TINYGLTF_COMPONENT_TYPE_FLOAT: size = 4; break;
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
  default: throw bad("component type must be float, or normalized unsigned byte or short");
  }
  if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) throw bad("buffer view out of range");
  const tinygltf::BufferView& v = model.bufferViews[size_t(a.bufferView)];
  if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size()) throw bad("buffer out of range");
  const auto& data = model.buffers[size_t(v.buffer)].data;
  const size_t element = size * size_t(components), stride = v.byteStride ? v.byteStride : element;
  if (a.count > (size_t(1) << 28) || stride < element) throw bad("implausible accessor layout");
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset) throw bad("buffer view beyond its buffer");
  if (a.count && (a.byteOffset > v.byteLength || (a.count - 1) * stride + element > v.byteLength - a.byteOffset))
    throw bad("accessor beyond its buffer view");
  std::vector<float> out(a.count * size_t(components));
  const unsigned char* base = data.data() + v.byteOffset + a.byteOffset;
  for (size_t i = 0; i < a.count; ++i)
    for (int c = 0; c < components; ++c) {
      const unsigned char* p = base + i * stride + size_t(c) * size;
      float value = 0.f;
      if (size == 4) std::memcpy(&value, p, 4);
      else if (size == 1) value = float(*p) / 255.f;
      else {
        uint16_t u;
        std::memcpy(&u, p, 2);
        value = float(u) / 65535.f;
      }
      if (!std::isfinite(value)) throw bad("a value is not a finite number");
      out[i * size_t(components) + size_t(c)] = value;
    }
  return out;
}

double colour_scale(const tinygltf::Mesh& mesh) {
  if (!mesh.extras.IsObject() || !mesh.extras.Has("hilight")) return 1.0;
  const tinygltf::Value& h = mesh.extras.Get("hilight");
  if (!h.IsObject() || !h.Has("colour_scale") || !h.Get("colour_scale").IsNumber()) return 1.0;
  const double s = h.Get("colour_scale").GetNumberAsDouble();
  return std::isfinite(s) && s > 0 ? s : 1.0;
}

} // namespace

namespace {

/// `extras.hilight` of a light: {"type": rectangle|disk|line, "size": [...], "up": [x, y, z]}.
Light area_from_extras(const tinygltf::Value& shape, const Vec3& position, const Vec3& direction, const Rgb& intensity,
                       const fs::path& path, const std::string& name) {
  LightType type = LightType::Point;
  const bool typed = shape.IsObject() && shape.Has("type") && shape.Get("type").IsString() &&
                     light_type_from_string(shape.Get("type").Get<std::string>(), type) && is_area(type);
  const tinygltf::Value size = typed && shape.Has("size") ? shape.Get("size") : tinygltf::Value();
  const tinygltf::Value up = typed && shape.Has("up") ? shape.Get("up") : tinygltf::Value();
  const size_t sizes = type == LightType::Rectangle ? 2 : 1;
  bool ok = typed && size.IsArray() && size.ArrayLen() == sizes && up.IsArray() && up.ArrayLen() == 3;
  glm::vec2 s(0.f);
  Vec3 u(0.f);
  for (size_t i = 0; ok && i < sizes; ++i) ok = size.Get(int(i)).IsNumber(), s[int(i)] = float(size.Get(int(i)).GetNumberAsDouble());
  for (int i = 0; ok && i < 3; ++i) ok = up.Get(i).IsNumber(), u[i] = float(up.Get(i).GetNumberAsDouble());
  Light light = Light::area(type, position, direction, ok ? u : Vec3(1.f, 0.f, 0.f), s, intensity);
  light.up = u;
  if (!ok || !area_light_problem(light).empty())
    throw InputError(path.string(), name + ": extras.hilight must be an area or line source's {\"type\", \"size\", \"up\"} (" +
                                        (ok ? area_light_problem(light) : std::string("malformed")) + ")");
  light.up = glm::normalize(u - glm::dot(u, light.direction) * light.direction);
  return light;
}

/// `extras.hilight` of a luminaire hilight wrote: {"type": "luminaire",
/// "profile": file, "aim", "spin_deg", "dimming"[, "shape": an area source's]}.
Light luminaire_from_extras(const tinygltf::Value& h, const Vec3& position, const fs::path& path, const std::string& name,
                            std::map<std::string, std::shared_ptr<const Photometry>>& profiles) {
  const auto bad = [&](const std::string& what) {
    return InputError(path.string(), name + ": extras.hilight of a luminaire: " + what);
  };
  if (!h.Has("profile") || !h.Get("profile").IsString()) throw bad("\"profile\" must name its .ies or .ldt file");
  const tinygltf::Value aim = h.Has("aim") ? h.Get("aim") : tinygltf::Value();
  if (!aim.IsArray() || aim.ArrayLen() != 3) throw bad("\"aim\" must be [x, y, z]");
  Vec3 direction(0.f);
  for (int i = 0; i < 3; ++i) {
    if (!aim.Get(i).IsNumber()) throw bad("\"aim\" must be [x, y, z]");
    direction[i] = float(aim.Get(i).GetNumberAsDouble());
  }
  if (!is_finite(direction) || !(glm::length(direction) > 1e-6f)) throw bad("\"aim\" must be a finite direction");
  const auto number = [&](const char* key, double fallback) {
    if (!h.Has(key)) return fallback;
    if (!h.Get(key).IsNumber() || !std::isfinite(h.Get(key).GetNumberAsDouble())) throw bad(std::string("\"") + key + "\" must be a number");
    return h.Get(key).GetNumberAsDouble();
  };
  const double dimming = number("dimming", 1.0), spin = number("spin_deg", 0.0);
  if (!(dimming >= 0 && dimming <= 1e6) || !(std::abs(spin) <= 360)) throw bad("\"dimming\" must be at least 0, \"spin_deg\" within ±360");
  const fs::path named = h.Get("profile").Get<std::string>();
  const fs::path file = named.is_absolute() ? named : path.parent_path() / named;
  // As its buffers: inside the glTF's folder only (issue 35), a regular file.
  if (!inside_folder(path.parent_path(), file))
    throw bad("its profile " + named_from(path.parent_path(), file) +
              " lies outside the glTF's folder (put the .ies or .ldt beside the glTF, or below it)");
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw bad("its profile " + named.string() + " is not a file there");
  const std::string key = fs::absolute(file).lexically_normal().string();
  auto& profile = profiles[key];
  if (!profile) profile = std::make_shared<const Photometry>(read_photometry(file));
  Light light;
  light.type = LightType::Luminaire;
  light.position = position;
  light.direction = glm::normalize(direction);
  light.profile = profile;
  light.profile_path = key;
  light.spin_deg = float(spin);
  light.intensity = Rgb(float(dimming * profile->peak() / kCandelaPerWattPerSr));
  if (h.Has("shape")) {
    Light area = area_from_extras(h.Get("shape"), position, light.direction, light.intensity, path, name);
    area.profile = light.profile;
    area.profile_path = light.profile_path;
    area.spin_deg = light.spin_deg;
    return area;
  }
  return light;
}

} // namespace

Lighting read_gltf_lights(const fs::path& path, const SceneFrame* frame) {
  const tinygltf::Model model = load(path);
  Lighting lights;
  std::map<std::string, std::shared_ptr<const Photometry>> profiles;
  for_each_node(model, path, [&](const tinygltf::Node& node, const glm::dmat4& world) {
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) return;
    const tinygltf::Value& ref = ext->second;
    if (!ref.IsObject() || !ref.Has("light") || !ref.Get("light").IsInt()) throw InputError(path.string(), "node '" + node.name + "': KHR_lights_punctual without a light index");
    const int index = ref.Get("light").GetNumberAsInt();
    if (index < 0 || size_t(index) >= model.lights.size()) throw InputError(path.string(), "node '" + node.name + "': light index out of range");
    const tinygltf::Light& g = model.lights[size_t(index)];
    const std::string name = "light '" + (g.name.empty() ? std::to_string(index) : g.name) + "'";
    if (g.type != "point" && g.type != "spot")
      throw InputError(path.string(), name + " is a " + g.type + " light; hilight has point lights and spotlights only");
    if (g.range > 0)
      throw InputError(path.string(), name + " has a range (" + std::to_string(g.range) +
                                          "); hilight's lights fall off by the inverse square without a cut-off: remove the range");
    Rgb colour(1.f);
    if (g.color.size() == 3) colour = Rgb(float(g.color[0]), float(g.color[1]), float(g.color[2]));
    const Rgb intensity = colour * float(g.intensity / kCandelaPerWattPerSr);
    if (!std::isfinite(intensity.r) || !std::isfinite(intensity.g) || !std::isfinite(intensity.b) || intensity.r < 0 ||
        intensity.g < 0 || intensity.b < 0)
      throw InputError(path.string(), name + ": colour and intensity must be finite and not negative");
    const glm::dvec3 world_position(world[3]);
    if (!std::isfinite(world_position.x) || !std::isfinite(world_position.y) || !std::isfinite(world_position.z))
      throw InputError(path.string(), name + ": its node's transform is not finite");
    // Into the scene's frame in double precision (scene_origin.hpp); a light the
    // move puts beyond float is the caller's to refuse (lights_from_file).
    const Vec3 position = frame ? to_local(world_position, *frame) : Vec3(world_position);
    if (g.extras.IsObject() && g.extras.Has("hilight") && g.extras.Get("hilight").IsObject() &&
        g.extras.Get("hilight").Has("type") && g.extras.Get("hilight").Get("type").IsString() &&
        g.extras.Get("hilight").Get("type").Get<std::string>() == "luminaire") {  // a luminaire hilight wrote (docs/interchange.md)
      lights.push_back(luminaire_from_extras(g.extras.Get("hilight"), position, path, name, profiles));
      if (frame && is_area(lights.back().type)) lights.back().size *= float(frame->scale);
      return;
    }
    if (g.type == "point") {
      lights.push_back(Light::point(position, intensity));
      return;
    }
    const glm::dvec3 axis = glm::dmat3(world) * glm::dvec3(0, 0, -1);
    const double outer = g.spot.outerConeAngle * 180.0 / kPi, inner = g.spot.innerConeAngle * 180.0 / kPi;
    if (glm::length(axis) <= 0 || !(outer > 0 && outer <= 90) || !(inner >= 0 && inner <= outer))
      throw InputError(path.string(), name + ": a spot needs 0 <= innerConeAngle <= outerConeAngle <= pi/2 and an axis");
    if (g.extras.IsObject() && g.extras.Has("hilight")) {  // an area or line source written by hilight (docs/interchange.md)
      lights.push_back(area_from_extras(g.extras.Get("hilight"), position, Vec3(glm::normalize(axis)), intensity, path, name));
      if (frame) lights.back().size *= float(frame->scale);
      return;
    }
    lights.push_back(Light::spot(position, Vec3(glm::normalize(axis)), float(outer), intensity, float(outer - inner)));
  });
  if (lights.empty()) throw InputError(path.string(), "no KHR_lights_punctual light in its default scene");
  return lights;
}

GltfColours read_gltf_colours(const fs::path& path, const std::string& attribute) {
  const tinygltf::Model model = load(path);
  GltfColours out;
  bool any_normals = true;
  // Primitives of one mesh often share their vertex accessors (one per
  // material): each node's vertices are read once.
  std::set<std::tuple<const tinygltf::Node*, int, int>> read;
  for_each_node(model, path, [&](const tinygltf::Node& node, const glm::dmat4& world) {
    if (node.mesh < 0) return;
    if (size_t(node.mesh) >= model.meshes.size()) throw InputError(path.string(), "node '" + node.name + "': mesh index out of range");
    const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
    const double scale = colour_scale(mesh);
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    for (const auto& primitive : mesh.primitives) {
      const auto colour = primitive.attributes.find(attribute), position = primitive.attributes.find("POSITION");
      if (colour == primitive.attributes.end() || position == primitive.attributes.end()) continue;
      if (!read.emplace(&node, position->second, colour->second).second) continue;
      const std::string what = "mesh '" + mesh.name + "'";
      int pc = 0, cc = 0, nc = 0;
      const auto p = read_floats(model, position->second, path, what + " POSITION", pc);
      const auto c = read_floats(model, colour->second, path, what + " " + attribute, cc);
      if (pc != 3 || (cc != 3 && cc != 4)) throw InputError(path.string(), what + ": POSITION must be VEC3 and " + attribute + " VEC3 or VEC4");
      const size_t count = p.size() / 3;
      if (c.size() / size_t(cc) != count) throw InputError(path.string(), what + ": " + attribute + " and POSITION differ in count");
      std::vector<float> n;
      if (const auto normal = primitive.attributes.find("NORMAL"); normal != primitive.attributes.end()) {
        n = read_floats(model, normal->second, path, what + " NORMAL", nc);
        if (nc != 3 || n.size() != p.size()) n.clear();
      }
      any_normals = any_normals && !n.empty();
      std::vector<float> w;  // a named weight attribute wins over alpha
      if (const auto weight = primitive.attributes.find("_WEIGHT"); weight != primitive.attributes.end()) {
        int wc = 0;
        w = read_floats(model, weight->second, path, what + " _WEIGHT", wc);
        if (wc != 1 || w.size() != count) throw InputError(path.string(), what + ": _WEIGHT must be SCALAR with one value per vertex");
      }
      for (size_t i = 0; i < count; ++i) {
        out.positions.push_back(Vec3(world * glm::dvec4(p[3 * i], p[3 * i + 1], p[3 * i + 2], 1.0)));
        if (!n.empty()) out.normals.push_back(glm::normalize(Vec3(normal_matrix * glm::dvec3(n[3 * i], n[3 * i + 1], n[3 * i + 2]))));
        const float* v = &c[i * size_t(cc)];
        out.values.push_back(Rgb(v[0], v[1], v[2]) * float(scale));
        out.weights.push_back(!w.empty() ? w[i] : cc == 4 ? v[3] : 1.f);
      }
    }
  });
  if (!any_normals) out.normals.clear();  // all or nothing: binding takes them per point
  if (out.positions.empty()) throw InputError(path.string(), "no mesh with " + attribute + " (vertex colours) in its default scene");
  return out;
}

} // namespace hilight
