#include "hilight/io/scene_io.hpp"
#include "hilight/scene_origin.hpp"

#include "hilight/error.hpp"
#include "hilight/io/tessellate.hpp"
#include "far_positions.hpp"
#include "scene_files.hpp"
#include "texture_average.hpp"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <fstream>
#include <sstream>

namespace hilight {

namespace fs = std::filesystem;

namespace {

// Scenes with more than this many triangles after tessellation are refused
// rather than exhausting memory on a too-small --max-edge.

Rgb material_albedo(const aiScene& scene, const aiMaterial& mat, const fs::path& folder, const std::string& file) {
  aiString name;
  mat.Get(AI_MATKEY_NAME, name);
  Rgb albedo(0.8f);
  aiColor4D c;
  // glTF's baseColorFactor first, then the classic diffuse colour (OBJ Kd).
  // Assimp invents "DefaultMaterial" for files without materials: treat as none.
  if (std::string(name.C_Str()) != AI_DEFAULT_MATERIAL_NAME &&
      (mat.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || mat.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)) {
    Rgb factor(c.r, c.g, c.b);
    if (is_finite(factor)) albedo = factor;
  }
  // A base-colour texture multiplies the factor; one average colour stands for it.
  std::string problem;
  if (auto texture = average_texture(scene, mat, folder, problem)) albedo *= *texture;
  else if (!problem.empty()) std::fprintf(stderr, "hilight: warning: %s: material %s: %s; its colour factor is used\n", file.c_str(), name.C_Str(), problem.c_str());
  return glm::clamp(albedo, Rgb(0.f), Rgb(1.f));
}

void validate(const Scene& scene, const std::string& file) {
  if (scene.triangles.empty()) throw InputError(file, "the scene has no triangles");
  size_t bad = 0;
  for (const auto& p : scene.positions) bad += !is_finite(p);
  if (bad) throw InputError(file, std::to_string(bad) + " vertices have NaN or infinite coordinates");
  for (const auto& t : scene.triangles)
    for (uint32_t v : t)
      if (v >= scene.positions.size()) throw InputError(file, "a face refers to vertex " + std::to_string(v) + " of " + std::to_string(scene.positions.size()));
  if (!(scene.diagonal() > 0.f)) throw InputError(file, "the scene has zero extent");
  if (!std::isfinite(scene.diagonal())) throw InputError(file, "coordinates too large: the scene's extent overflows single precision");
}

// Drops zero-area triangles and fills missing or degenerate normals from faces.
void clean(Scene& scene) {
  std::vector<std::array<uint32_t, 3>> tris;
  std::vector<uint32_t> mats;
  std::vector<Vec3> acc(scene.positions.size(), Vec3(0.f));
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    Vec3 n = glm::cross(scene.positions[tri[1]] - scene.positions[tri[0]], scene.positions[tri[2]] - scene.positions[tri[0]]);
    if (!(glm::length(n) > 0.f)) continue;
    for (uint32_t v : tri) acc[v] += n;
    tris.push_back(tri);
    mats.push_back(scene.triangle_material[t]);
  }
  scene.triangles = std::move(tris);
  scene.triangle_material = std::move(mats);
  scene.normals.resize(scene.positions.size(), Vec3(0.f));
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    float len = glm::length(scene.normals[v]);
    if (!(len > 0.f) || !std::isfinite(len)) {
      float alen = glm::length(acc[v]);
      scene.normals[v] = alen > 0.f ? acc[v] / alen : Vec3(0.f, 0.f, 1.f);
    } else {
      scene.normals[v] /= len;
    }
  }
}

} // namespace

namespace {

// Assimp's OFF reader allocates whatever the header claims before reading a
// single vertex, so a tiny file claiming billions of elements exhausts memory.
// Each vertex and face takes at least a few bytes of text: check the claim
// against the file's size first.
void check_off_header(const fs::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = char(std::tolower(c));
  if (ext != ".off") return;
  std::ifstream in(path);
  // Skip the keyword (OFF, COFF, NOFF, ...) and # comments; then come the
  // vertex and face counts.
  std::string word;
  while (in >> word && (word[0] == '#' || std::isalpha(static_cast<unsigned char>(word[0]))))
    if (word[0] == '#') std::getline(in, word);
  double vertices = std::strtod(word.c_str(), nullptr), faces = 0;
  if (!(in >> faces)) return;  // let assimp say what is wrong
  std::error_code ec;
  const double size = double(fs::file_size(path, ec));
  // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8.
  if (ec || !(vertices * 6 + faces * 8 > size * 1.01 + 64)) return;
  std::ostringstream message;
  message << "the OFF header claims " << vertices << " vertices and " << faces << " faces, more than the file can hold";
  throw InputError(path.string(), message.str());
}

// assimp's PLY reader skips whitespace after end_header even in a binary
// file: data starting with a byte such as 0x0a (the float -0.02) shifts every
// value after it, and the mesh comes in garbled, or fails on an index out of
// range. Refuse such a file rather than read it wrong.
void check_binary_ply_start(const fs::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = char(std::tolower(c));
  if (ext != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool binary = false;
  for (int lines = 0; std::getline(in, line) && lines < 10000; ++lines) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("format binary", 0) == 0) binary = true;
    if (line == "end_header") break;
  }
  const int first = in.get();
  if (!binary || first == std::char_traits<char>::eof() || !std::isspace(first)) return;
  throw InputError(path.string(),
                   "binary PLY whose data starts with a whitespace byte, which assimp (hilight's scene reader) misreads: "
                   "save it as ASCII PLY, or with another vertex order or a leading property");
}

/// A far scene assimp read in single precision from a more precise file
/// (glTF node transforms, OFF, ASCII STL, ...): rounded before it was moved
/// home. Said once, with how much.
void warn_rounded(const std::string& file, const Bounds& world, const SceneFrame& frame) {
  double largest = 0;
  for (int axis = 0; axis < 3; ++axis) largest = std::max({largest, std::abs(double(world.lo[axis])), std::abs(double(world.hi[axis]))});
  const double error_mm = far_positions::float_rounding(largest) * frame.scale * 1000.0;
  // Only a rounding that matters against the scene's own size (its ε is 10⁻⁵
  // of it) is worth a line; a scene a metre off, or one that is not finite, is not.
  const double size_mm = double(glm::length(world.hi - world.lo)) * frame.scale * 1000.0;
  if (!(error_mm > 1e-6 * size_mm)) return;
  std::fprintf(stderr,
               "hilight: warning: %s: its positions were read in single precision (assimp) %.3g m from the origin: "
               "rounded by up to %.2g mm before the scene was moved home (OBJ and ASCII PLY are read in full)\n",
               file.c_str(), largest * frame.scale, error_mm);
}

} // namespace

Scene finish_scene(Scene scene, const SceneLoadOptions& options) {
  scene.update_bounds();
  validate(scene, scene.source);
  clean(scene);
  if (scene.triangles.empty()) throw InputError(scene.source, "the scene has no triangles of non-zero area");
  scene.input_vertex_count = scene.positions.size();
  scene.input_triangle_count = scene.triangles.size();
  float diag = scene.diagonal();
  float max_edge = options.max_edge > 0.f ? options.max_edge : diag * kDefaultEdgeFraction;
  // Estimate the result's size before committing memory to it.
  double estimate = 0;
  for (const auto& t : scene.triangles) {
    float longest = 0.f;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, glm::length(scene.positions[t[k]] - scene.positions[t[(k + 1) % 3]]));
    double ratio = std::max(1.0, double(longest) / max_edge);
    estimate += ratio * ratio;
  }
  // A tessellated mesh has about half as many vertices as triangles (Euler).
  const double vertices = std::max(double(scene.positions.size()), 0.5 * estimate);
  if (!(vertices <= double(options.max_vertices))) {
    char text[200];
    std::snprintf(text, sizeof(text), "--max-edge %g would make about %.3g vertices, more than --max-vertices %zu (a larger --max-edge, or a larger limit if the memory is there)",
                  double(max_edge), vertices, options.max_vertices);
    throw InputError(scene.source, text);
  }
  tessellate(scene, max_edge);
  scene.max_edge = max_edge;
  return scene;
}

Scene load_scene(const fs::path& path, const SceneLoadOptions& options) {
  const std::string file = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(file, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(file, "is a folder, not a scene file");
  if (!std::ifstream(path, std::ios::binary)) throw InputError(file, "cannot open (permission denied?)");

  check_off_header(path);
  check_binary_ply_start(path);
  // Positions in double where hilight can read them, moved home before
  // assimp's floats round them (far_positions.hpp).
  const far_positions::Shifted shifted = far_positions::read(path);
  Assimp::Importer importer;
  auto* files = new SceneFiles(path, shifted.text);  // the importer owns it
  importer.SetIOHandler(files);
  // Points and lines carry no surface: drop them during import.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 60.f);
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                         aiProcess_GenSmoothNormals | aiProcess_SortByPType | aiProcess_FindDegenerates |
                         aiProcess_ValidateDataStructure;
  const aiScene* ai = importer.ReadFile(file, flags);
  // A file named outside the folder was refused unread; so is the scene.
  if (!files->outside().empty())
    throw InputError(file, "refers to " + files->outside() + ", outside its folder (the files it names must lie in its folder or below)");
  if (!ai) throw InputError(file, std::string("cannot read scene: ") + importer.GetErrorString());

  Scene scene;
  scene.source = file;
  for (unsigned m = 0; m < ai->mNumMaterials; ++m) {
    aiString name;
    ai->mMaterials[m]->Get(AI_MATKEY_NAME, name);
    scene.materials.push_back({name.C_Str(), material_albedo(*ai, *ai->mMaterials[m], path.parent_path(), file)});
  }
  if (scene.materials.empty()) scene.materials.push_back({"default", Rgb(0.8f)});
  for (unsigned mi = 0; mi < ai->mNumMeshes; ++mi) {
    const aiMesh& mesh = *ai->mMeshes[mi];
    if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    uint32_t base = uint32_t(scene.positions.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      scene.positions.emplace_back(p.x, p.y, p.z);
      if (mesh.mNormals) scene.normals.emplace_back(mesh.mNormals[v].x, mesh.mNormals[v].y, mesh.mNormals[v].z);
      else scene.normals.emplace_back(0.f);
    }
    uint32_t material = mesh.mMaterialIndex < scene.materials.size() ? mesh.mMaterialIndex : 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      scene.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
      scene.triangle_material.push_back(material);
    }
  }
  // Its unit, then home from far away, exactly, in metres (scene_origin.hpp).
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const bool ifc = ext == ".ifc" || ext == ".ifczip", gltf = ext == ".gltf" || ext == ".glb", metric = ifc || gltf;
  scene.frame.unit = options.unit.empty() ? "m" : options.unit;
  scene.frame.scale = metres_per_unit(scene.frame.unit);
  if (ifc && scene.frame.unit != "m")
    throw InputError(file, "IFC files say their unit (assimp converts it to metres): --unit " + scene.frame.unit + " does not apply");
  // glTF is in metres by its specification, but some files were written in
  // another unit (Khronos' 2CylinderEngine in millimetres: 766 m across
  // read as metres, its cavities as large as rooms): --unit overrides, said.
  if (gltf && scene.frame.unit != "m")
    std::fprintf(stderr, "hilight: note: %s: glTF is in metres by its specification; read in %s, as --unit says\n", file.c_str(),
                 scene.frame.unit.c_str());
  scene.update_bounds();
  if (!shifted.text.empty()) {  // already moved home, in double: scaled only
    scene.frame.origin = shifted.origin;
    for (auto& p : scene.positions) p = Vec3(glm::dvec3(p) * scene.frame.scale);
  } else {
    scene.frame.origin = recentring_origin(scene.bounds);
    if (!scene.frame.identity())
      for (auto& p : scene.positions) p = to_local(p, scene.frame);
    if (scene.frame.origin != glm::dvec3(0.0) && shifted.precision == far_positions::Precision::Rounded)
      warn_rounded(file, scene.bounds, scene.frame);
  }
  SceneLoadOptions in_metres = options;
  in_metres.max_edge = options.max_edge > 0.f ? length_to_local(options.max_edge, scene.frame) : 0.f;
  Scene out = finish_scene(std::move(scene), in_metres);
  // A size no model has in its unit is said once: the unit is likely wrong.
  const double metres = double(out.diagonal());  // hilight's are metres
  if (metres < 0.01 || metres > 5000.0)
    std::fprintf(stderr, "hilight: warning: %s is %.3g m across in %s%s: if that is not its size, give --unit (mm, cm, m, in, ft)\n",
                 file.c_str(), metres, out.frame.unit == "m" ? "metres" : out.frame.unit.c_str(),
                 options.unit.empty() && !metric ? " (the default: the file does not say)" : "");
  return out;
}

} // namespace hilight
