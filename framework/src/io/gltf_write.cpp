// glTF out: one buffer, the scene as one mesh (a primitive per material,
// sharing the vertex accessors), a node per light with KHR_lights_punctual.
#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/units.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <stdexcept>
#include <tiny_gltf.h>

namespace hilight {

namespace fs = std::filesystem;

bool is_gltf_path(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

namespace {

/// Builds the buffer and its views and accessors as data is added.
class BufferWriter {
public:
  explicit BufferWriter(tinygltf::Model& model) : m_model(model) { m_model.buffers.emplace_back(); }

  /// Appends `count` elements of `components` floats; returns the accessor.
  int floats(const float* data, size_t count, int type, int components, int target, bool with_bounds) {
    const int view = add_view(data, count * size_t(components) * sizeof(float), target);
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = count;
    a.type = type;
    if (with_bounds) {  // POSITION needs min and max (spec)
      a.minValues.assign(size_t(components), 1e300);
      a.maxValues.assign(size_t(components), -1e300);
      for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < components; ++c) {
          a.minValues[size_t(c)] = std::min(a.minValues[size_t(c)], double(data[i * size_t(components) + size_t(c)]));
          a.maxValues[size_t(c)] = std::max(a.maxValues[size_t(c)], double(data[i * size_t(components) + size_t(c)]));
        }
    }
    m_model.accessors.push_back(a);
    return int(m_model.accessors.size() - 1);
  }

  int indices(const std::vector<uint32_t>& data) {
    const int view = add_view(data.data(), data.size() * sizeof(uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.count = data.size();
    a.type = TINYGLTF_TYPE_SCALAR;
    m_model.accessors.push_back(a);
    return int(m_model.accessors.size() - 1);
  }

private:
  int add_view(const void* data, size_t bytes, int target) {
    auto& buffer = m_model.buffers[0].data;
    while (buffer.size() % 4) buffer.push_back(0);  // 4-byte alignment of every view
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer.size();
    v.byteLength = bytes;
    v.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    m_model.bufferViews.push_back(v);
    return int(m_model.bufferViews.size() - 1);
  }
  tinygltf::Model& m_model;
};

/// Per-vertex colours as RGBA floats divided by `scale`.
std::vector<float> rgba(const std::vector<Rgb>& values, const std::vector<float>* alpha, float scale) {
  std::vector<float> out(values.size() * 4);
  for (size_t i = 0; i < values.size(); ++i) {
    for (int c = 0; c < 3; ++c) out[4 * i + size_t(c)] = values[i][c] / scale;
    out[4 * i + 3] = alpha ? (*alpha)[i] : 1.f;
  }
  return out;
}

void add_mesh(tinygltf::Model& model, BufferWriter& buffers, const GltfExport& in, tinygltf::Node& node) {
  const Scene& scene = *in.scene;
  const size_t n = scene.positions.size();
  tinygltf::Mesh mesh;
  mesh.name = scene.source.empty() ? "scene" : fs::path(scene.source).filename().string();
  std::map<std::string, int> attributes;
  attributes["POSITION"] = buffers.floats(&scene.positions[0].x, n, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  attributes["NORMAL"] = buffers.floats(&scene.normals[0].x, n, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  // Illumination is not bounded by 1: both colour sets are divided by their
  // common largest channel, kept as extras.hilight.colour_scale to undo it.
  float scale = 0.f;
  for (const auto* set : {&in.result, &in.target})
    for (const auto& c : *set) scale = std::max({scale, c.r, c.g, c.b});
  if (scale <= 0.f) scale = 1.f;
  if (!in.result.empty()) {
    const auto colours = rgba(in.result, nullptr, scale);
    attributes["COLOR_0"] = buffers.floats(colours.data(), n, TINYGLTF_TYPE_VEC4, 4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  if (!in.target.empty()) {
    const auto colours = rgba(in.target, &in.target_weight, scale);
    attributes[in.result.empty() ? "COLOR_0" : "COLOR_1"] =
        buffers.floats(colours.data(), n, TINYGLTF_TYPE_VEC4, 4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  if (!in.result.empty() || !in.target.empty()) {
    tinygltf::Value::Object extras;
    extras["colour_scale"] = tinygltf::Value(double(scale));
    extras["colours"] = tinygltf::Value(std::string(in.result.empty() ? "COLOR_0: target (alpha: weight)"
                                                    : in.target.empty() ? "COLOR_0: result"
                                                                        : "COLOR_0: result, COLOR_1: target (alpha: weight)"));
    tinygltf::Value::Object wrapped;
    wrapped["hilight"] = tinygltf::Value(std::move(extras));
    mesh.extras = tinygltf::Value(std::move(wrapped));
  }
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    std::vector<uint32_t> indices;
    for (size_t t = 0; t < scene.triangles.size(); ++t)
      if (scene.triangle_material[t] == m) indices.insert(indices.end(), scene.triangles[t].begin(), scene.triangles[t].end());
    if (indices.empty()) continue;
    tinygltf::Material material;
    material.name = scene.materials[m].name;
    const Rgb a = scene.materials[m].albedo;
    material.pbrMetallicRoughness.baseColorFactor = {a.r, a.g, a.b, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;  // hilight's surfaces are Lambertian
    material.pbrMetallicRoughness.roughnessFactor = 1.0;
    model.materials.push_back(material);
    tinygltf::Primitive primitive;
    primitive.attributes = attributes;
    primitive.indices = buffers.indices(indices);
    primitive.material = int(model.materials.size() - 1);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    mesh.primitives.push_back(primitive);
  }
  model.meshes.push_back(mesh);
  node.mesh = int(model.meshes.size() - 1);
  node.name = mesh.name;
}

/// The rotation taking −Z (a glTF light's axis) to `direction`.
glm::dquat aim(const Vec3& direction) {
  const glm::dvec3 from(0, 0, -1), to = glm::normalize(glm::dvec3(direction));
  const double d = glm::dot(from, to);
  if (d < -1.0 + 1e-12) return glm::dquat(0, 1, 0, 0);  // opposite: half a turn about X
  const glm::dvec3 axis = glm::cross(from, to);
  return glm::normalize(glm::dquat(1.0 + d, axis.x, axis.y, axis.z));
}

/// An area or line source as what Blender imports: a hemisphere spot (90°
/// cone, its edge soft from the axis) of I0 along the normal; its true shape
/// in the light's `extras.hilight`, which reading restores (docs/interchange.md).
void add_area_extras(const Light& l, tinygltf::Light& light, tinygltf::Node& node) {
  light.spot.outerConeAngle = kPi / 2;
  light.spot.innerConeAngle = 0.0;
  const glm::dquat q = aim(l.direction);
  node.rotation = {q.x, q.y, q.z, q.w};
  tinygltf::Value::Object shape;
  shape["type"] = tinygltf::Value(std::string(to_string(l.type)));
  tinygltf::Value::Array size{tinygltf::Value(double(l.size[0]))};
  if (l.type == LightType::Rectangle) size.push_back(tinygltf::Value(double(l.size[1])));
  shape["size"] = tinygltf::Value(std::move(size));
  shape["up"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(double(l.up.x)), tinygltf::Value(double(l.up.y)),
                                                      tinygltf::Value(double(l.up.z))});
  tinygltf::Value::Object extras;
  extras["hilight"] = tinygltf::Value(std::move(shape));
  light.extras = tinygltf::Value(std::move(extras));
}

tinygltf::Value numbers(std::initializer_list<double> values) {
  tinygltf::Value::Array a;
  for (double v : values) a.push_back(tinygltf::Value(v));
  return tinygltf::Value(std::move(a));
}

/// A luminaire with a measured profile as what Blender imports: a spot
/// aimed along its nadir when its light stays in the lower hemisphere (the
/// cone to where its C-averaged intensity falls below 1% of its largest,
/// the soft edge from where it falls below half), of that largest C-averaged
/// intensity; else a point of its mean intensity (flux / 4π). The profile
/// file, aim, spin, dimming and flux (and an area source's shape) go in
/// `extras.hilight`, from which hilight reads the luminaire back
/// (docs/interchange.md).
void add_luminaire(const Light& l, tinygltf::Light& light, tinygltf::Node& node, const fs::path& path) {
  const Photometry& p = *l.profile;
  const double dimming = luminaire_dimming(l);
  std::vector<double> mean(181, 0.0);
  for (int g = 0; g <= 180; ++g) {
    for (int c = 0; c < 360; c += 5) mean[size_t(g)] += p.intensity(double(c), double(g));
    mean[size_t(g)] /= 72.0;
  }
  const double largest = *std::max_element(mean.begin(), mean.end());
  int cutoff = 0, half = 0;
  for (int g = 0; g <= 180; ++g) {
    if (mean[size_t(g)] >= 0.01 * largest) cutoff = g;
    if (mean[size_t(g)] >= 0.5 * largest && half == g) half = g + 1;
  }
  half = std::max(0, half - 1);
  const glm::dquat q = aim(l.direction);
  node.rotation = {q.x, q.y, q.z, q.w};
  if (cutoff <= 90) {
    light.type = "spot";
    light.spot.outerConeAngle = std::max(1, cutoff) * kPi / 180.0;
    light.spot.innerConeAngle = std::min(half, std::max(0, cutoff - 1)) * kPi / 180.0;
    light.intensity = dimming * largest;
  } else {
    light.type = "point";
    light.intensity = dimming * p.flux() / (4.0 * kPi);
  }
  light.color = {1.0, 1.0, 1.0};
  tinygltf::Value::Object extras;
  extras["type"] = tinygltf::Value(std::string("luminaire"));
  // Named from the glTF's folder when it lies there or below (the only place reading takes it from), else absolute.
  const fs::path folder = fs::absolute(path).parent_path().lexically_normal(), profile = fs::absolute(l.profile_path).lexically_normal();
  const fs::path relative = profile.lexically_relative(folder);
  const bool below = !relative.empty() && *relative.begin() != "..";
  extras["profile"] = tinygltf::Value(below ? relative.generic_string() : profile.string());
  extras["aim"] = numbers({l.direction.x, l.direction.y, l.direction.z});
  extras["spin_deg"] = tinygltf::Value(double(l.spin_deg));
  extras["dimming"] = tinygltf::Value(dimming);
  extras["luminous_flux_lm"] = tinygltf::Value(dimming * p.flux());
  if (p.input_watts > 0) extras["power_w"] = tinygltf::Value(dimming * p.input_watts);
  if (!p.product.empty()) extras["product"] = tinygltf::Value(p.product);
  if (is_area(l.type)) {
    tinygltf::Value::Object shape;
    shape["type"] = tinygltf::Value(std::string(to_string(l.type)));
    tinygltf::Value::Array size{tinygltf::Value(double(l.size[0]))};
    if (l.type == LightType::Rectangle) size.push_back(tinygltf::Value(double(l.size[1])));
    shape["size"] = tinygltf::Value(std::move(size));
    shape["up"] = numbers({l.up.x, l.up.y, l.up.z});
    extras["shape"] = tinygltf::Value(std::move(shape));
  }
  tinygltf::Value::Object wrapped;
  wrapped["hilight"] = tinygltf::Value(std::move(extras));
  light.extras = tinygltf::Value(std::move(wrapped));
}

void add_light(tinygltf::Model& model, const Light& l, size_t index, const glm::dvec3& origin, tinygltf::Node& node,
               const fs::path& path) {
  if ((l.type == LightType::Luminaire || is_area(l.type)) && l.profile && l.profile_path.empty())
    throw InputError(path.string(), "light " + std::to_string(index) + " is a luminaire whose profile has no file to name in the glTF");
  tinygltf::Light light;
  light.name = "light " + std::to_string(index);
  light.type = l.type == LightType::Spot || is_area(l.type) ? "spot" : "point";
  const double largest = std::max({double(l.intensity.r), double(l.intensity.g), double(l.intensity.b)});
  light.color = largest > 0 ? std::vector<double>{l.intensity.r / largest, l.intensity.g / largest, l.intensity.b / largest}
                            : std::vector<double>{1.0, 1.0, 1.0};
  light.intensity = largest * kCandelaPerWattPerSr;
  if (l.type == LightType::Spot) {
    light.spot.outerConeAngle = double(l.cutoff_deg) * kPi / 180.0;
    light.spot.innerConeAngle = std::max(0.0, double(l.cutoff_deg - l.falloff_deg) * kPi / 180.0);
    const glm::dquat q = aim(l.direction);
    node.rotation = {q.x, q.y, q.z, q.w};
  }
  if (l.profile) add_luminaire(l, light, node, path);
  else if (is_area(l.type)) add_area_extras(l, light, node);
  model.lights.push_back(light);
  node.name = light.name;
  const glm::dvec3 world = glm::dvec3(l.position) + origin;  // exact in the file's doubles
  node.translation = {world.x, world.y, world.z};
  tinygltf::Value::Object reference;
  reference["light"] = tinygltf::Value(int(model.lights.size() - 1));
  node.extensions["KHR_lights_punctual"] = tinygltf::Value(std::move(reference));
}

} // namespace

void write_gltf(const fs::path& path, const GltfExport& in) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "hilight";
  BufferWriter buffers(model);
  tinygltf::Scene scene;
  if (in.scene && !in.scene->positions.empty()) {
    tinygltf::Node node;
    add_mesh(model, buffers, in, node);
    // A scene moved home when loaded (scene_origin.hpp): its vertices stay
    // local, the node puts them back where they were.
    // glTF is in metres: the origin too.
    const glm::dvec3 origin = in.scene->frame.origin * in.scene->frame.scale;
    if (origin != glm::dvec3(0.0)) node.translation = {origin.x, origin.y, origin.z};
    model.nodes.push_back(node);
    scene.nodes.push_back(int(model.nodes.size() - 1));
  }
  for (size_t j = 0; j < in.lights.size(); ++j) {
    tinygltf::Node node;
    add_light(model, in.lights[j], j, in.scene ? in.scene->frame.origin * in.scene->frame.scale : glm::dvec3(0.0), node, path);
    model.nodes.push_back(node);
    scene.nodes.push_back(int(model.nodes.size() - 1));
  }
  if (!in.lights.empty()) model.extensionsUsed.push_back("KHR_lights_punctual");
  if (!in.figures.empty()) {
    tinygltf::Value::Object figures;
    for (const auto& [name, value] : in.figures) figures[name] = tinygltf::Value(value);
    tinygltf::Value::Object wrapped;
    wrapped["hilight"] = tinygltf::Value(std::move(figures));
    scene.extras = tinygltf::Value(std::move(wrapped));
  }
  scene.name = "hilight";
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  if (model.buffers[0].data.empty()) model.buffers.clear();
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const bool binary = ext == ".glb";
  write_atomically(path, [&](std::ostream& out) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, binary))
      throw InputError(path.string(), "cannot write: the glTF writer failed");
  });
}

} // namespace hilight
