// What keeps a building's solve and painter in memory: the light cache's nodes
// kept in blocks of vertices as on disk (lit runs only),
// and one ray scene shared by everything that binds a scene.
#include "hilight/io/scene_io.hpp"
#include "hilight/light_cache_nodes.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <random>
#include <sstream>

using namespace hilight;

namespace {

/// Passes every call to `inner`, counting release_scratch().
class ScratchCounter final : public Renderer {
public:
  explicit ScratchCounter(Renderer& inner) : m_inner(inner) {}
  void set_scene(std::shared_ptr<const Scene>) override {}
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override {
    return m_inner.illuminate(points, lights);
  }
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport) override {
    ++calls;
    largest_call = std::max(largest_call, points.size());
    return m_inner.unit_responses(points, lights, transport);
  }
  std::string settings_key() const override { return m_inner.settings_key(); }
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override {
    return m_inner.render_image(camera, lights, width, height);
  }
  void release_scratch() override {
    ++releases;
    m_inner.release_scratch();
  }
  size_t releases = 0, largest_call = 0, calls = 0;

private:
  Renderer& m_inner;
};

std::shared_ptr<const Scene> curved() { return std::make_shared<const Scene>(finish_scene(builders::curved_models_on_floor(), {})); }

} // namespace

TEST_CASE("light cache nodes on the IFC house: traced a few nodes a call at every vertex, the same as one call over all nodes, "
          "kept in blocks without the dark vertices and read back bit for bit",
          "[cache][memory]") {
  auto scene = std::make_shared<const Scene>(load_scene(builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"));
  REQUIRE(scene->positions.size() > 2 * NodeResponses::kBlock);
  auto embree = test::make_renderer("embree", scene, {"bounce_samples=16"});
  ScratchCounter renderer(*embree);
  // Seeded random nodes inside the house's box (some in rooms, some outside or in walls).
  std::mt19937_64 rng(19);
  const Bounds box = scene->light_bounds();
  std::vector<Vec3> positions;
  for (int k = 0; k < 5; ++k) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = std::uniform_real_distribution<float>(box.lo[a], box.hi[a])(rng);
    positions.push_back(p);
  }
  NodeResponses nodes(scene->positions.size());
  nodes.trace(*scene, renderer, positions);
  REQUIRE(nodes.count() == positions.size());
  REQUIRE(nodes.blocks() >= 3);
  // Every vertex in each call: a renderer with further bounces transports a
  // light over the whole scene whatever points it is asked about, so a call
  // per block transported each node's light once per block (issue 33).
  CHECK(renderer.calls == 1);
  CHECK(renderer.largest_call == scene->positions.size());

  // One renderer call over every vertex gives the same bounce: a point's
  // gather depends on the point, not on the set it came in.
  Lighting lights;
  for (const Vec3& p : positions) lights.push_back(Light::point(p, Rgb(1.f)));
  const SurfacePoints all = SurfacePoints::from_vertices(*scene);
  const std::vector<Rgb> whole = embree->unit_responses(all, lights, Transport::IndirectOnly);
  const size_t vc = scene->positions.size();
  std::vector<Rgb> unpacked(NodeResponses::kBlock);
  size_t dark = 0;
  for (size_t n = 0; n < nodes.count(); ++n)
    for (size_t block = 0; block < nodes.blocks(); ++block) {
      const size_t lo = block * NodeResponses::kBlock, count = std::min(NodeResponses::kBlock, vc - lo);
      float largest = 0.f;
      for (size_t v = lo; v < lo + count; ++v) largest = std::max({largest, whole[n * vc + v].r, whole[n * vc + v].g, whole[n * vc + v].b});
      nodes.block_values(n, block, unpacked.data());
      for (size_t v = lo; v < lo + count; ++v) {
        const Rgb kept = nodes.value(n, v), exact = whole[n * vc + v];
        INFO("node " << n << " vertex " << v);
        REQUIRE(kept == unpacked[v - lo]);
        // Half floats over the block's largest channel: 11 significant bits,
        // and values below half's normal range flush towards 0.
        for (int c = 0; c < 3; ++c) REQUIRE(std::abs(kept[c] - exact[c]) <= 1e-3f * exact[c] + 1e-4f * largest);
        dark += kept == Rgb(0.f);
      }
    }
  // Walls hide most of the house from most nodes: those vertices take no memory.
  INFO("dark vertex-nodes " << dark << " of " << nodes.count() * vc << "; kept " << nodes.memory_bytes() << " bytes");
  CHECK(dark > nodes.count() * vc / 4);
  CHECK(nodes.memory_bytes() < 6 * (nodes.count() * vc - dark) + 4096 * nodes.count() * nodes.blocks());

  // The disk's bytes give back the same numbers, bit for bit; cut short or
  // with a run past its block, they are refused.
  std::stringstream file;
  nodes.write(file);
  const std::string bytes = file.str();
  NodeResponses read;
  std::istringstream in(bytes);
  REQUIRE(read.read(in, vc, nodes.count()));
  for (size_t n = 0; n < nodes.count(); ++n)
    for (size_t v = 0; v < vc; v += 7) REQUIRE(read.value(n, v) == nodes.value(n, v));
  std::istringstream cut(bytes.substr(0, bytes.size() - 5));
  CHECK_FALSE(NodeResponses().read(cut, vc, nodes.count()));
  std::istringstream wrong_vertices(bytes);
  CHECK_FALSE(NodeResponses().read(wrong_vertices, vc - NodeResponses::kBlock / 2, nodes.count()));
}

TEST_CASE("one ray scene per scene, shared by every renderer and solver that binds it, gone with the last of them", "[memory]") {
  auto scene = curved();
  std::weak_ptr<const RayScene> first;
  {
    const auto a = RayScene::shared(scene), b = RayScene::shared(scene);
    CHECK(a.get() == b.get());
    CHECK(&a->scene() == scene.get());
    auto other = curved();
    CHECK(RayScene::shared(other).get() != a.get());
    first = a;
  }
  CHECK(first.expired());
  // It keeps its scene alive while it is held.
  auto held = RayScene::shared(curved());
  CHECK(held->scene().triangles.size() == scene->triangles.size());
  CHECK(held->intersect(scene->bounds.center() + Vec3(0.f, scene->diagonal(), 0.f), Vec3(0.f, -1.f, 0.f)).valid());
}
