// glTF in and out (issue 13): lights as KHR_lights_punctual by the spec,
// targets from vertex colours, the same solve from a glTF as from PLY/JSON,
// and the broken glTF files of assimp-testmodels refused in one line.
#include "hilight/error.hpp"
#include "hilight/fixtures/built_scenes.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/target.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <random>

using namespace hilight;

namespace {

/// Seeded point lights and spots aimed every way (straight up and down too).
Lighting random_mix(uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(-1.f, 1.f), pos(0.f, 5.f), bright(0.05f, 40.f);
  Lighting lights;
  for (int i = 0; i < 12; ++i) {
    const Vec3 p(pos(rng), pos(rng), pos(rng));
    const Rgb intensity(bright(rng), bright(rng), bright(rng));
    if (i % 2 == 0) {
      lights.push_back(Light::point(p, intensity));
      continue;
    }
    Vec3 d = i == 1 ? Vec3(0, -1, 0) : i == 3 ? Vec3(0, 1, 0) : i == 5 ? Vec3(0, 0, 1) : Vec3(u(rng), u(rng), u(rng));
    if (glm::length(d) < 0.1f) d = Vec3(1, 0, 0);
    const float cutoff = 5.f + 80.f * (0.5f + 0.5f * u(rng));
    lights.push_back(Light::spot(p, d, cutoff, intensity, cutoff * (0.5f + 0.5f * u(rng))));
  }
  return lights;
}

void check_same_lights(const Lighting& back, const Lighting& lights) {
  REQUIRE(back.size() == lights.size());
  for (size_t j = 0; j < lights.size(); ++j) {
    INFO("light " << j);
    CHECK(back[j].type == lights[j].type);
    CHECK(glm::length(back[j].position - lights[j].position) < 1e-5f);
    for (int c = 0; c < 3; ++c) CHECK(back[j].intensity[c] == Approx(lights[j].intensity[c]).epsilon(1e-5));
    if (lights[j].type != LightType::Spot) continue;
    CHECK(glm::dot(back[j].direction, lights[j].direction) > 1.f - 1e-6f);
    CHECK(back[j].cutoff_deg == Approx(lights[j].cutoff_deg).epsilon(1e-5));
    CHECK(back[j].falloff_deg == Approx(lights[j].falloff_deg).margin(1e-4));
  }
}

nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

/// A scene file, lights and the PLY and glTF targets `hilight` makes of them.
struct Exported {
  std::filesystem::path dir, scene, lights, ply, glb;
};

Exported export_room(const std::string& name, const Lighting& truth) {
  Exported e;
  e.dir = test::output_dir("gltf_" + name);
  e.scene = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  e.lights = e.dir / "truth.json";
  write_lights_json(e.lights, truth);
  e.ply = e.dir / "target.ply";
  e.glb = e.dir / "target.glb";
  REQUIRE(test::run_hilight({"render", e.scene.string(), "--lights", e.lights.string(), "-o", e.ply.string()}).exit_code == 0);
  const auto exported = test::run_hilight({"export", e.scene.string(), "--lights", e.lights.string(), "-o", e.glb.string(), "--vertex-colours"});
  INFO(exported.err);
  REQUIRE(exported.exit_code == 0);
  return e;
}

} // namespace

TEST_CASE("glTF lights round trip, in .gltf and .glb, for seeded point lights and spots", "[gltf]") {
  const auto dir = test::output_dir("gltf_lights");
  for (uint64_t seed : {1, 2, 3}) {
    const Lighting lights = random_mix(seed);
    for (const char* name : {"l.gltf", "l.glb"}) {
      INFO("seed " << seed << ", " << name);
      write_gltf(dir / name, GltfExport{nullptr, lights});
      check_same_lights(read_gltf_lights(dir / name), lights);
    }
  }
}

TEST_CASE("glTF lights follow KHR_lights_punctual: candela, colour split, cones, -Z along the spot", "[gltf]") {
  const auto dir = test::output_dir("gltf_spec");
  const Lighting lights = {Light::point({1.f, 2.f, 3.f}, Rgb(2.f, 1.f, 0.5f)),
                           Light::spot({0.f, 3.f, 0.f}, {1.f, -1.f, 0.f}, 40.f, Rgb(3.f), 10.f)};
  GltfExport out{nullptr, lights};
  out.figures = {{"lights", 2}, {"dbar", 0.0125}};
  write_gltf(dir / "l.gltf", out);
  const auto j = read_json(dir / "l.gltf");
  CHECK(j["asset"]["version"] == "2.0");
  CHECK(std::find(j["extensionsUsed"].begin(), j["extensionsUsed"].end(), "KHR_lights_punctual") != j["extensionsUsed"].end());
  const auto& gl = j["extensions"]["KHR_lights_punctual"]["lights"];
  REQUIRE(gl.size() == 2);
  CHECK(gl[0]["type"] == "point");
  CHECK(gl[0]["intensity"].get<double>() == Approx(2.0 * 683.0));  // cd = 683 × W/sr of the brightest channel
  CHECK(gl[0]["color"][0].get<double>() == Approx(1.0));
  CHECK(gl[0]["color"][2].get<double>() == Approx(0.25));
  CHECK(gl[1]["type"] == "spot");
  CHECK(gl[1]["spot"]["outerConeAngle"].get<double>() == Approx(40.0 * kPi / 180.0));
  CHECK(gl[1]["spot"]["innerConeAngle"].get<double>() == Approx(30.0 * kPi / 180.0));
  // The spot's node turns −Z onto its direction.
  const auto& node = j["nodes"][1];
  const glm::dquat q(node["rotation"][3].get<double>(), node["rotation"][0].get<double>(), node["rotation"][1].get<double>(),
                     node["rotation"][2].get<double>());
  const glm::dvec3 axis = q * glm::dvec3(0, 0, -1);
  CHECK(glm::dot(axis, glm::normalize(glm::dvec3(1, -1, 0))) == Approx(1.0));
  CHECK(node["extensions"]["KHR_lights_punctual"]["light"] == 1);
  CHECK(j["scenes"][0]["extras"]["hilight"]["dbar"].get<double>() == Approx(0.0125));
}

TEST_CASE("glTF lights under transformed parent nodes are read in world space", "[gltf]") {
  // A parent turned 90° about +Y and moved; its child light 1 m along its own
  // −Z (a spot aiming down its −Z): in the world at (−1, 2, 0) + (3, 0, 0), aiming −X.
  const auto dir = test::output_dir("gltf_hierarchy");
  const double s = std::sqrt(0.5);
  const nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes",
       {{{"translation", {3, 0, 0}}, {"rotation", {0, s, 0, s}}, {"children", {1}}},
        {{"translation", {0, 2, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
      {"extensions",
       {{"KHR_lights_punctual",
         {{"lights", {{{"type", "spot"}, {"intensity", 683.0}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}}}}}}}}};
  std::ofstream(dir / "h.gltf") << doc.dump();
  const Lighting l = read_gltf_lights(dir / "h.gltf");
  REQUIRE(l.size() == 1);
  CHECK(glm::length(l[0].position - Vec3(4.f, 2.f, 0.f)) < 1e-5f);
  CHECK(glm::dot(l[0].direction, Vec3(-1.f, 0.f, 0.f)) > 0.99999f);
  CHECK(l[0].intensity.r == Approx(1.0));
  CHECK(l[0].cutoff_deg == Approx(0.5 * 180.0 / kPi));
  CHECK(l[0].falloff_deg == Approx(0.3 * 180.0 / kPi));
}

TEST_CASE("a glTF target (COLOR_0) binds like the PLY target of the same illumination", "[gltf][target]") {
  const Lighting truth = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f, 1.9f, 1.7f))};
  const Exported e = export_room("target", truth);
  auto scene = std::make_shared<const Scene>(load_scene(e.scene, {}));
  RayScene rays(*scene);
  const Target from_ply = read_target(e.ply, *scene, rays), from_gltf = read_target(e.glb, *scene, rays);
  REQUIRE(from_gltf.size() == from_ply.size());
  size_t same_vertex = 0;
  for (size_t i = 0; i < from_ply.size(); ++i) {
    same_vertex += from_gltf.vertex[i] == from_ply.vertex[i];
    for (int c = 0; c < 3; ++c) CHECK(from_gltf.value[i][c] == Approx(from_ply.value[i][c]).epsilon(1e-5).margin(1e-9));
  }
  CHECK(same_vertex == from_ply.size());
  // Weights: alpha, or a _WEIGHT attribute; 0 drops the point.
  GltfExport out;
  out.scene = scene.get();
  out.target.assign(scene->positions.size(), Rgb(0.5f));
  out.target_weight.assign(scene->positions.size(), 1.f);
  for (size_t v = 0; v < scene->positions.size(); v += 3) out.target_weight[v] = v % 2 ? 0.25f : 0.f;
  write_gltf(e.dir / "weighted.gltf", out);
  const GltfColours colours = read_gltf_colours(e.dir / "weighted.gltf");
  REQUIRE(colours.weights.size() == scene->positions.size());
  CHECK(colours.weights[3] == 0.25f);
  CHECK(colours.weights[6] == 0.f);
  CHECK(colours.values[1].g == Approx(0.5f));
  const Target weighted = read_target(e.dir / "weighted.gltf", *scene, rays);
  CHECK(weighted.size() == scene->positions.size() - (scene->positions.size() + 5) / 6);
}

TEST_CASE("hilight solve from a glTF target to a glTF output finds what the PLY path finds", "[gltf][cli][solve]") {
  const Lighting truth = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f, 1.9f, 1.7f)),
                          Light::point({2.3f, 1.6f, 3.9f}, Rgb(1.6f, 1.7f, 2.f))};
  const Exported e = export_room("solve", truth);
  auto solve = [&](const std::filesystem::path& target, const std::string& out) {
    const auto r = test::run_hilight({"solve", e.scene.string(), "--target", target.string(), "-o", (e.dir / out).string(),
                                      "--cache-dir", (e.dir / "cache").string(), "--report", (e.dir / (out + ".report.json")).string(),
                                      "--vertex-colours"});
    INFO(r.err);
    CHECK(r.exit_code == (out.ends_with(".json") ? 2 : 0));  // --vertex-colours wants a glTF output
    return r;
  };
  CHECK_THAT(solve(e.ply, "lights.json").err, Catch::Contains("--vertex-colours needs a .gltf or .glb output"));
  const auto r = test::run_hilight({"solve", e.scene.string(), "--target", e.ply.string(), "-o", (e.dir / "lights.json").string(),
                                    "--cache-dir", (e.dir / "cache").string(), "--report", (e.dir / "ply.report.json").string()});
  REQUIRE(r.exit_code == 0);
  solve(e.glb, "lights.glb");
  const Lighting from_ply = read_lights_json(e.dir / "lights.json"), from_gltf = read_gltf_lights(e.dir / "lights.glb");
  REQUIRE(from_gltf.size() == from_ply.size());
  CHECK(from_gltf.size() == truth.size());
  for (const auto& t : truth) {
    float nearest = 1e9f;
    for (const auto& l : from_gltf) nearest = std::min(nearest, glm::length(l.position - t.position));
    CHECK(nearest < 0.05f);
  }
  const double dbar_ply = read_json(e.dir / "ply.report.json")["dbar"], dbar_gltf = read_json(e.dir / "lights.glb.report.json")["dbar"];
  CHECK(dbar_gltf == Approx(dbar_ply).margin(1e-4));
  // The output carries the scene, the count and D̄, and COLOR_0/COLOR_1 on its mesh.
  const GltfColours result = read_gltf_colours(e.dir / "lights.glb"), target = read_gltf_colours(e.dir / "lights.glb", "COLOR_1");
  CHECK(result.values.size() == target.values.size());
  // A glTF of lights is an --initial: the truth is a fixed point.
  write_gltf(e.dir / "truth.glb", GltfExport{nullptr, truth});
  const auto tune = test::run_hilight({"solve", e.scene.string(), "--target", e.glb.string(), "-o", (e.dir / "tuned.gltf").string(),
                                       "--mode", "fine-tune", "--initial", (e.dir / "truth.glb").string(), "--cache-dir",
                                       (e.dir / "cache").string(), "--report", (e.dir / "tuned.report.json").string()});
  INFO(tune.err);
  REQUIRE(tune.exit_code == 0);
  CHECK(read_json(e.dir / "tuned.report.json")["dbar"].get<double>() < 0.001);
  check_same_lights(read_gltf_lights(e.dir / "tuned.gltf"), read_gltf_lights(e.dir / "truth.glb"));
}

TEST_CASE("broken and light-less glTF files are refused in one line with exit 2 and no output", "[gltf][bad-input]") {
  const std::filesystem::path models = builders::testmodels_dir() / "glTF2";
  const auto dir = test::output_dir("gltf_bad");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  std::vector<std::filesystem::path> files = {
      models / "IndexOutOfRange/IndexOutOfRange.gltf",     models / "IndexOutOfRange/AllIndicesOutOfRange.gltf",
      models / "RecursiveNodes/RecursiveNodes.gltf",       models / "MissingBin/BoxTextured.gltf",
      models / "wrongTypes/badArray.gltf",                 models / "wrongTypes/badNumber.gltf",
      models / "SchemaFailures/sceneWrongType.gltf",       models / "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
      models / "IncorrectVertexArrays/Cube.gltf",          models / "BoxTextured-glTF/BoxTextured.gltf" /* no lights, no colours */};
  std::ofstream(dir / "garbage.glb") << "glTF\x02\x00\x00\x00 not really";
  files.push_back(dir / "garbage.glb");
  size_t tried = 0;
  for (const auto& f : files) {
    if (!std::filesystem::exists(f)) continue;  // assimp-testmodels versions differ
    ++tried;
    for (const std::string as : {"--lights", "--target"}) {
      INFO(f << " as " << as);
      const auto out = dir / "out.ply";
      std::filesystem::remove(out);
      const auto r = as == "--lights"
                         ? test::run_hilight({"render", room, "--lights", f.string(), "-o", out.string()})
                         : test::run_hilight({"solve", room, "--target", f.string(), "-o", (dir / "l.json").string(), "--no-cache"});
      CHECK(r.exit_code == 2);
      CHECK(test::line_count(r.err) == 1);
      CHECK_THAT(r.err, Catch::Contains(f.filename().string()));
      CHECK_FALSE(std::filesystem::exists(out));
      CHECK_FALSE(std::filesystem::exists(dir / "l.json"));
    }
  }
  CHECK(tried >= 8);
}

TEST_CASE("a glTF scene written by hilight renders with its own lights as the original scene does", "[gltf][cli]") {
  const Lighting truth = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::spot({4.f, 2.8f, 3.f}, {0.f, -1.f, 0.2f}, 35.f, Rgb(5.f), 8.f)};
  const Exported e = export_room("scene_lights", truth);
  const auto from_obj = e.dir / "obj.ply", from_glb = e.dir / "glb.ply";
  REQUIRE(test::run_hilight({"render", e.scene.string(), "--lights", e.lights.string(), "-o", from_obj.string(), "--bounces", "0"}).exit_code == 0);
  const auto r = test::run_hilight({"render", e.glb.string(), "-o", from_glb.string(), "--bounces", "0"});  // no --lights: the file's own
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const PlyVertices a = read_ply_vertices(from_obj), b = read_ply_vertices(from_glb);
  std::map<std::tuple<float, float, float, float, float, float>, size_t> index;
  auto key = [](const PlyVertices& p, size_t i) {
    return std::make_tuple(float(p.properties.at("x")[i]), float(p.properties.at("y")[i]), float(p.properties.at("z")[i]),
                           float(std::round(p.properties.at("nx")[i] * 100)), float(std::round(p.properties.at("ny")[i] * 100)),
                           float(std::round(p.properties.at("nz")[i] * 100)));
  };
  for (size_t i = 0; i < a.count; ++i) index[key(a, i)] = i;
  size_t matched = 0;
  for (size_t i = 0; i < b.count; ++i) {
    const auto found = index.find(key(b, i));
    if (found == index.end()) continue;
    ++matched;
    for (const char* c : {"red", "green", "blue"})
      CHECK(b.properties.at(c)[i] == Approx(a.properties.at(c)[found->second]).epsilon(1e-4).margin(1e-7));
  }
  CHECK(matched > a.count * 9 / 10);
  // Without lights in the file, and without --lights, render says what is missing.
  const auto none = test::run_hilight({"render", e.scene.string(), "-o", (e.dir / "none.ply").string()});
  CHECK(none.exit_code == 2);
  CHECK(test::line_count(none.err) == 1);
}

TEST_CASE("glTF written by hilight keeps the spec's rules for accessors, buffer views and the lights extension", "[gltf]") {
  const auto dir = test::output_dir("gltf_valid");
  auto scene = std::make_shared<const Scene>(load_scene(std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj", {}));
  GltfExport out;
  out.scene = scene.get();
  out.lights = random_mix(9);
  out.result.assign(scene->positions.size(), Rgb(3.f, 2.f, 1.f));
  out.target.assign(scene->positions.size(), Rgb(1.f));
  out.target_weight.assign(scene->positions.size(), 1.f);
  write_gltf(dir / "s.gltf", out);
  const auto j = read_json(dir / "s.gltf");
  const size_t buffer_bytes = j["buffers"][0]["byteLength"];
  CHECK(j["buffers"][0]["uri"].get<std::string>().rfind("data:application/octet-stream;base64,", 0) == 0);
  for (const auto& v : j["bufferViews"]) {
    CHECK(v["buffer"] == 0);
    CHECK(v.value("byteOffset", 0) % 4 == 0);
    CHECK(v.value("byteOffset", 0) + v["byteLength"].get<size_t>() <= buffer_bytes);
  }
  const std::map<std::string, size_t> components = {{"SCALAR", 1}, {"VEC3", 3}, {"VEC4", 4}};
  for (const auto& a : j["accessors"]) {
    const auto& v = j["bufferViews"][a["bufferView"].get<size_t>()];
    const size_t size = a["componentType"] == 5126 || a["componentType"] == 5125 ? 4 : 0;
    REQUIRE(size == 4);
    CHECK(a.value("byteOffset", 0) + a["count"].get<size_t>() * components.at(a["type"]) * size <= v["byteLength"].get<size_t>());
  }
  for (const auto& p : j["meshes"][0]["primitives"]) {
    const auto& position = j["accessors"][p["attributes"]["POSITION"].get<size_t>()];
    CHECK(position.contains("min"));  // required for POSITION
    CHECK(position.contains("max"));
    for (const char* attribute : {"NORMAL", "COLOR_0", "COLOR_1"})
      CHECK(j["accessors"][p["attributes"][attribute].get<size_t>()]["count"] == position["count"]);
    CHECK(j["accessors"][p["indices"].get<size_t>()]["componentType"] == 5125);
    CHECK(p["material"].get<size_t>() < j["materials"].size());
  }
  const auto& lights = j["extensions"]["KHR_lights_punctual"]["lights"];
  size_t referenced = 0;
  for (const auto& n : j["nodes"])
    if (n.contains("extensions")) {
      CHECK(n["extensions"]["KHR_lights_punctual"]["light"].get<size_t>() < lights.size());
      ++referenced;
    }
  CHECK(referenced == lights.size());
  for (const auto& l : lights) {
    CHECK(l["intensity"].get<double>() >= 0);
    for (const auto& c : l["color"]) CHECK((c.get<double>() >= 0 && c.get<double>() <= 1));
    if (l["type"] == "spot") CHECK(l["spot"]["innerConeAngle"].get<double>() < l["spot"]["outerConeAngle"].get<double>());
  }
  // The colours are in [0, 1] with the scale that undoes them in the mesh's extras.
  CHECK(j["meshes"][0]["extras"]["hilight"]["colour_scale"].get<double>() == Approx(3.0));
  CHECK(read_gltf_colours(dir / "s.gltf").values[0].r == Approx(3.f));
}

TEST_CASE("glTF lights with a range, and COLOR_0 of the wrong length, are refused in one line", "[gltf][bad-input]") {
  const auto dir = test::output_dir("gltf_bad_fields");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  nlohmann::json ranged = {{"asset", {{"version", "2.0"}}},
                           {"scenes", {{{"nodes", {0}}}}},
                           {"nodes", {{{"translation", {1, 2, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
                           {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"range", 4.0}}}}}}}}};
  std::ofstream(dir / "ranged.gltf") << ranged.dump();
  const auto r = test::run_hilight({"render", room, "--lights", (dir / "ranged.gltf").string(), "-o", (dir / "out.ply").string()});
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("range"));
  CHECK_FALSE(std::filesystem::exists(dir / "out.ply"));
  // COLOR_0 with one vertex fewer than POSITION.
  auto scene = std::make_shared<const Scene>(load_scene(room, {}));
  GltfExport out;
  out.scene = scene.get();
  out.result.assign(scene->positions.size(), Rgb(0.5f));
  write_gltf(dir / "colours.gltf", out);
  auto j = read_json(dir / "colours.gltf");
  const size_t colour = j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"];
  j["accessors"][colour]["count"] = j["accessors"][colour]["count"].get<size_t>() - 1;
  std::ofstream(dir / "short.gltf") << j.dump();
  const auto s = test::run_hilight({"solve", room, "--target", (dir / "short.gltf").string(), "-o", (dir / "l.json").string(), "--no-cache"});
  CHECK(s.exit_code == 2);
  CHECK(test::line_count(s.err) == 1);
  CHECK_THAT(s.err, Catch::Contains("COLOR_0 and POSITION differ in count"));
  CHECK_FALSE(std::filesystem::exists(dir / "l.json"));
}
