// Good paths of the `hilight` launcher: info, render (PLY, PNG, EXR), plugins,
// and the refusal of modules built for another ABI / build key.
#include "hilight/version.hpp"
#include "support.hpp"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-lights.json";


/// A binary little-endian PLY as hilight writes it.
struct Ply {
  std::vector<std::string> header;  ///< every header line, "ply" .. "end_header"
  std::vector<std::array<float, 9>> vertices;  ///< x y z nx ny nz red green blue
  std::vector<std::array<int32_t, 3>> faces;
};

/// Reads the PLY, checking the exact layout hilight promises; fails the test otherwise.
Ply read_ply(const fs::path& path) {
  std::string bytes = test::read_file(path);
  REQUIRE(bytes.size() > 4);
  Ply ply;
  size_t pos = 0;
  for (;;) {
    size_t nl = bytes.find('\n', pos);
    REQUIRE(nl != std::string::npos);
    ply.header.push_back(bytes.substr(pos, nl - pos));
    pos = nl + 1;
    if (ply.header.back() == "end_header") break;
    REQUIRE(ply.header.size() < 100);
  }
  // The header without comments must be exactly this, in this order.
  std::vector<std::string> lines;
  for (const auto& l : ply.header)
    if (l.rfind("comment", 0) != 0) lines.push_back(l);
  REQUIRE(lines.size() == 15);
  CHECK(lines[0] == "ply");
  CHECK(lines[1] == "format binary_little_endian 1.0");
  size_t vertex_count = 0, face_count = 0;
  {
    std::istringstream ss(lines[2]);
    std::string element, name;
    ss >> element >> name >> vertex_count;
    REQUIRE(element == "element");
    REQUIRE(name == "vertex");
    REQUIRE(ss);
  }
  const char* props[9] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};
  for (int i = 0; i < 9; ++i) CHECK(lines[3 + i] == std::string("property float ") + props[i]);
  {
    std::istringstream ss(lines[12]);
    std::string element, name;
    ss >> element >> name >> face_count;
    REQUIRE(element == "element");
    REQUIRE(name == "face");
    REQUIRE(ss);
  }
  CHECK(lines[13] == "property list uchar int vertex_indices");
  CHECK(lines[14] == "end_header");

  REQUIRE(bytes.size() == pos + vertex_count * 9 * sizeof(float) + face_count * (1 + 3 * sizeof(int32_t)));
  ply.vertices.resize(vertex_count);
  if (vertex_count) std::memcpy(ply.vertices.data(), bytes.data() + pos, vertex_count * 9 * sizeof(float));
  pos += vertex_count * 9 * sizeof(float);
  ply.faces.resize(face_count);
  for (size_t f = 0; f < face_count; ++f) {
    REQUIRE(uint8_t(bytes[pos]) == 3);
    std::memcpy(ply.faces[f].data(), bytes.data() + pos + 1, 3 * sizeof(int32_t));
    pos += 1 + 3 * sizeof(int32_t);
  }
  return ply;
}

uint32_t big_endian_u32(const std::string& bytes, size_t at) {
  return (uint32_t(uint8_t(bytes[at])) << 24) | (uint32_t(uint8_t(bytes[at + 1])) << 16) |
         (uint32_t(uint8_t(bytes[at + 2])) << 8) | uint32_t(uint8_t(bytes[at + 3]));
}

nlohmann::json info_json(const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"info", kRoom, "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  auto r = test::run_hilight(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

test::RunResult render(const std::vector<std::string>& outputs, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"render", kRoom, "--lights", kRoomLights};
  for (const auto& o : outputs) {
    args.push_back("-o");
    args.push_back(o);
  }
  args.insert(args.end(), extra.begin(), extra.end());
  auto r = test::run_hilight(args);
  CAPTURE(r.out, r.err);
  REQUIRE(r.exit_code == 0);
  return r;
}

/// Sets an environment variable for one scope and restores the old state.
class ScopedEnv {
public:
  ScopedEnv(const char* name, const std::string& value) : m_name(name) {
    if (const char* old = std::getenv(name)) m_old = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (m_old) ::setenv(m_name, m_old->c_str(), 1);
    else ::unsetenv(m_name);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
  const char* m_name;
  std::optional<std::string> m_old;
};

/// The `hilight plugins` row for NAME: {kind, name, version, status}.
std::optional<std::array<std::string, 4>> plugin_row(const std::string& listing, const std::string& name) {
  std::istringstream lines(listing);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream ss(line);
    std::array<std::string, 4> row;
    ss >> row[0] >> row[1] >> row[2];
    std::getline(ss >> std::ws, row[3]);
    if (row[1] == name) return row;
  }
  return std::nullopt;
}

} // namespace

TEST_CASE("info: the demo room's size, bounds and diagonal", "[cli][render]") {
  SECTION("text") {
    auto r = test::run_hilight({"info", kRoom});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    CHECK_THAT(r.out, Contains("triangles") && Contains("(input 108)"));
    CHECK_THAT(r.out, Contains("vertices"));
    CHECK_THAT(r.out, Contains("bounds     [0, 0, 0] .. [6, 3, 5]"));
    CHECK_THAT(r.out, Contains("diagonal   8.3666"));
  }
  SECTION("json") {
    auto j = info_json();
    CHECK(j.at("triangles_input").get<size_t>() == 108);
    CHECK(j.at("file").get<std::string>() == kRoom);
    CHECK(j.at("triangles").get<size_t>() > 108);
    CHECK(j.at("vertices").get<size_t>() > j.at("vertices_input").get<size_t>());
    CHECK(j.at("bounds_min") == nlohmann::json::array({0.0, 0.0, 0.0}));
    CHECK(j.at("bounds_max") == nlohmann::json::array({6.0, 3.0, 5.0}));
    CHECK(j.at("diagonal").get<double>() == Approx(std::sqrt(36.0 + 9.0 + 25.0)).epsilon(1e-6));
    // Default edge: diagonal / 40.
    CHECK(j.at("max_edge").get<double>() == Approx(std::sqrt(70.0) / 40.0).epsilon(1e-6));
  }
}

TEST_CASE("info and render: --max-edge bounds every edge of the tessellation", "[cli][render]") {
  auto fine = info_json();
  auto coarse = info_json({"--max-edge", "0.5"});
  CHECK(coarse.at("max_edge").get<double>() == Approx(0.5));
  CHECK(coarse.at("triangles_input") == fine.at("triangles_input"));
  CHECK(coarse.at("vertices").get<size_t>() < fine.at("vertices").get<size_t>());
  CHECK(coarse.at("vertices").get<size_t>() >= coarse.at("vertices_input").get<size_t>());

  fs::path dir = test::output_dir("cli_render_max_edge");
  render({(dir / "coarse.ply").string()}, {"--max-edge", "0.5", "--bounces", "0", "--refine-shadows", "0"});
  Ply ply = read_ply(dir / "coarse.ply");
  CHECK(ply.vertices.size() == coarse.at("vertices").get<size_t>());
  CHECK(ply.faces.size() == coarse.at("triangles").get<size_t>());
  float longest = 0.f;
  size_t too_long = 0;
  for (const auto& f : ply.faces) {
    for (int k = 0; k < 3; ++k) {
      int32_t a = f[k], b = f[(k + 1) % 3];
      REQUIRE(a >= 0);
      REQUIRE(size_t(a) < ply.vertices.size());
      const auto &p = ply.vertices[size_t(a)], &q = ply.vertices[size_t(b)];
      float len = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
      longest = std::max(longest, len);
      too_long += len > 0.5f + 1e-5f;
    }
  }
  CAPTURE(longest);
  CHECK(too_long == 0);
  CHECK(longest > 0.25f);  // not refined needlessly far
}

TEST_CASE("render: OUT writes a per-vertex PLY and a PNG of the requested size", "[cli][render]") {
  fs::path dir = test::output_dir("cli_render_ply_png");
  auto r = render({(dir / "out").string()}, {"--bounces", "0", "--width", "64", "--height", "48", "--refine-shadows", "0"});
  CHECK_THAT(r.err, Contains("out.ply") && Contains("out.png"));
  CHECK(r.out.empty());
  REQUIRE(fs::exists(dir / "out.ply"));
  REQUIRE(fs::exists(dir / "out.png"));

  Ply ply = read_ply(dir / "out.ply");
  auto info = info_json();
  CHECK(ply.vertices.size() == info.at("vertices").get<size_t>());
  CHECK(ply.faces.size() == info.at("triangles").get<size_t>());
  size_t lit = 0, bad = 0, bad_normal = 0, out_of_bounds = 0;
  for (const auto& v : ply.vertices) {
    for (int c = 6; c < 9; ++c) bad += !(std::isfinite(v[c]) && v[c] >= 0.f);
    lit += v[6] + v[7] + v[8] > 0.f;
    float n = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
    bad_normal += !(std::abs(n - 1.f) < 1e-3f);
    out_of_bounds += !(v[0] >= -1e-4f && v[0] <= 6.0001f && v[1] >= -1e-4f && v[1] <= 3.0001f && v[2] >= -1e-4f && v[2] <= 5.0001f);
  }
  CHECK(bad == 0);
  CHECK(bad_normal == 0);
  CHECK(out_of_bounds == 0);
  CHECK(lit > ply.vertices.size() / 4);  // four lights inside the room: much of it is lit
  CHECK(lit < ply.vertices.size());      // but not everything (shadows, backs of furniture)
  for (const auto& f : ply.faces)
    for (int32_t i : f) {
      REQUIRE(i >= 0);
      REQUIRE(size_t(i) < ply.vertices.size());
    }

  std::string png = test::read_file(dir / "out.png");
  REQUIRE(png.size() > 33);
  CHECK(png.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) == 0);
  CHECK(png.compare(12, 4, "IHDR") == 0);
  CHECK(big_endian_u32(png, 16) == 64);
  CHECK(big_endian_u32(png, 20) == 48);
}

TEST_CASE("render: the same render twice gives byte-identical PLY files", "[cli][render]") {
  fs::path dir = test::output_dir("cli_render_determinism");
  std::vector<std::string> opts;
  SECTION("direct light") { opts = {"--bounces", "0"}; }
  SECTION("first bounce") { opts = {"--bounces", "1", "--bounce-samples", "16"}; }
  CAPTURE(opts);
  render({(dir / "a.ply").string()}, opts);
  render({(dir / "b.ply").string()}, opts);
  std::string a = test::read_file(dir / "a.ply"), b = test::read_file(dir / "b.ply");
  REQUIRE(a.size() > 1000);
  CHECK(a.size() == b.size());
  CHECK((a == b));
}

TEST_CASE("render: the first bounce adds light to the direct-only result", "[cli][render]") {
  fs::path dir = test::output_dir("cli_render_bounce");
  render({(dir / "direct.ply").string()}, {"--bounces", "0"});
  render({(dir / "bounce.ply").string()}, {"--bounces", "1", "--bounce-samples", "16"});
  Ply direct = read_ply(dir / "direct.ply"), bounce = read_ply(dir / "bounce.ply");
  REQUIRE(direct.vertices.size() == bounce.vertices.size());
  double sum_direct = 0, sum_bounce = 0;
  size_t darker = 0, unlit_direct = 0, lit_by_bounce = 0;
  for (size_t i = 0; i < direct.vertices.size(); ++i) {
    double d = double(direct.vertices[i][6]) + direct.vertices[i][7] + direct.vertices[i][8];
    double b = double(bounce.vertices[i][6]) + bounce.vertices[i][7] + bounce.vertices[i][8];
    sum_direct += d;
    sum_bounce += b;
    darker += b < d * (1 - 1e-4) - 1e-7;
    if (d == 0) {
      ++unlit_direct;
      lit_by_bounce += b > 0;
    }
  }
  CHECK(darker == 0);  // the bounce only adds light
  CHECK(sum_bounce > sum_direct * 1.01);
  if (unlit_direct > 0) CHECK(lit_by_bounce > 0);
}

TEST_CASE("render: OUT.exr writes an OpenEXR image", "[cli][render]") {
  fs::path dir = test::output_dir("cli_render_exr");
  auto r = render({(dir / "out.exr").string()}, {"--bounces", "0", "--width", "64", "--height", "48"});
  CHECK_THAT(r.err, Contains("out.exr"));
  std::string exr = test::read_file(dir / "out.exr");
  REQUIRE(exr.size() > 64 * 48);  // at least one byte per pixel
  CHECK(uint8_t(exr[0]) == 0x76);
  CHECK(uint8_t(exr[1]) == 0x2f);
  CHECK(uint8_t(exr[2]) == 0x31);
  CHECK(uint8_t(exr[3]) == 0x01);
  CHECK_FALSE(fs::exists(dir / "out.ply"));
  CHECK_FALSE(fs::exists(dir / "out.png"));
  // Nothing but the one file.
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("plugins: the embree renderer and the cli frontend are ok", "[cli][render]") {
  auto r = test::run_hilight({"plugins"});
  CAPTURE(r.out, r.err);
  REQUIRE(r.exit_code == 0);
  auto embree = plugin_row(r.out, "embree");
  auto cli = plugin_row(r.out, "cli");
  REQUIRE(embree);
  REQUIRE(cli);
  CHECK((*embree)[0] == "renderer");
  CHECK((*cli)[0] == "frontend");
  CHECK((*embree)[2] == HILIGHT_VERSION);
  CHECK((*embree)[3].rfind("ok", 0) == 0);
  CHECK((*cli)[3].rfind("ok", 0) == 0);
}

TEST_CASE("plugins: modules for another ABI or build key are listed as not loaded and refused", "[cli][render]") {
  REQUIRE(fs::exists(fs::path(HILIGHT_TEST_PLUGIN_DIR) / "hilight-renderer-wrong-abi.so"));
  REQUIRE(fs::exists(fs::path(HILIGHT_TEST_PLUGIN_DIR) / "hilight-renderer-wrong-key.so"));
  test::RunResult listing, abi_render, key_render;
  fs::path dir = test::output_dir("cli_render_refused_plugins");
  {
    ScopedEnv env("HILIGHT_PLUGIN_PATH", HILIGHT_TEST_PLUGIN_DIR);
    listing = test::run_hilight({"plugins"});
    abi_render = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", (dir / "abi.ply").string(),
                                    "--renderer", "wrong-abi", "--bounces", "0"});
    key_render = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", (dir / "key.ply").string(),
                                    "--renderer", "wrong-key", "--bounces", "0"});
  }
  {
    CAPTURE(listing.out, listing.err);
    REQUIRE(listing.exit_code == 0);
    auto abi = plugin_row(listing.out, "hilight-renderer-wrong-abi");
    auto key = plugin_row(listing.out, "hilight-renderer-wrong-key");
    REQUIRE(abi);
    REQUIRE(key);
    CHECK_THAT((*abi)[3], Contains("not loaded") && Contains("ABI version"));
    CHECK_THAT((*key)[3], Contains("not loaded") && Contains("othercc-99/otherlib/c++1"));
    // The good modules still load beside them.
    auto embree = plugin_row(listing.out, "embree");
    REQUIRE(embree);
    CHECK((*embree)[3].rfind("ok", 0) == 0);
  }
  {
    CAPTURE(abi_render.out, abi_render.err);
    CHECK(abi_render.exit_code == 2);
    CHECK(test::line_count(abi_render.err) == 1);
    CHECK_THAT(abi_render.err, Contains("wrong-abi") && Contains("ABI version"));
  }
  {
    CAPTURE(key_render.out, key_render.err);
    CHECK(key_render.exit_code == 2);
    CHECK(test::line_count(key_render.err) == 1);
    CHECK_THAT(key_render.err, Contains("wrong-key"));
  }
  CHECK(fs::is_empty(dir));
  // The variable is gone again: the refused modules are not listed.
  if (!std::getenv("HILIGHT_PLUGIN_PATH")) {
    auto after = test::run_hilight({"plugins"});
    CHECK_FALSE(plugin_row(after.out, "hilight-renderer-wrong-abi"));
  }
}
