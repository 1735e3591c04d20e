#pragma once
/// The one way to assemble a solve: from a registry, a SolveSpec (which
/// plugins, their settings, the solve's settings) and a scene, the reference
/// renderer, its fast twin, the sampler, the optimizer and the light cache
/// plugin, and the Solvers
/// over them. `hilight solve`, `hilight bench solve` and the painter all
/// build their solve here, so the same input gives the same lights anywhere.
#include "hilight/solve/solver.hpp"
#include "hilight/registry.hpp"

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hilight {

struct SolveSpec {
  std::string renderer = PluginDefaults::renderer;
  std::vector<std::string> renderer_settings;  ///< key=value, as the user set up the renderer
  std::string optimizer = PluginDefaults::optimizer;
  std::vector<std::string> optimizer_settings;
  std::string sampler = PluginDefaults::sampler;
  std::vector<std::string> sampler_settings;
  std::string cache = PluginDefaults::cache;  ///< PluginDefaults::no_cache: every φ from the renderer
  std::vector<std::string> cache_settings;
  SolveSettings settings;  ///< its seed also seeds the renderers' sample streams
};

class SolveSession {
public:
  /// Unknown or unavailable plugins, and settings they do not read, are
  /// InputErrors here, before any work.
  SolveSession(const Registry& registry, SolveSpec spec, std::shared_ptr<const Scene> scene,
               std::shared_ptr<const RayScene> rays = nullptr);

  /// Checks the plugin names of `spec` without a scene (fail before loading one).
  static void check_names(const Registry& registry, const SolveSpec& spec);

  /// A Solver over the session's parts with `settings` (by default the spec's).
  std::unique_ptr<Solver> make_solver(ProgressFn progress = {}) const { return make_solver(m_spec.settings, std::move(progress)); }
  std::unique_ptr<Solver> make_solver(const SolveSettings& settings, ProgressFn progress = {}) const;

  const SolveSpec& spec() const { return m_spec; }
  /// The reference's settings (the user's, with the seed): a renderer made
  /// with them renders what the solve measures.
  const std::vector<std::string>& reference_settings() const { return m_reference_settings; }
  /// The fast twin's settings with the renderer's preview ones added, or
  /// nothing when the renderer declares no preview or the user chose any of
  /// its keys (RendererTraits::preview).
  std::vector<std::string> preview_settings() const;
  /// A new renderer of the session's kind with `settings`, bound to the scene.
  std::unique_ptr<Renderer> make_renderer(const std::vector<std::string>& settings) const;

  const std::shared_ptr<const Scene>& scene() const { return m_scene; }
  const std::shared_ptr<const RayScene>& rays() const { return m_rays; }
  Renderer& reference() { return *m_reference; }
  /// The fast twin, made on first use: a criteria solve or a render needs
  /// the reference alone (a second GPU context, a second pass over the
  /// vertices, for nothing).
  Renderer& fast() const;

private:
  const Registry& m_registry;
  SolveSpec m_spec;
  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_rays;
  std::vector<std::string> m_reference_settings, m_fast_settings;
  std::unique_ptr<Renderer> m_reference;
  mutable std::once_flag m_fast_once;
  mutable std::unique_ptr<Renderer> m_fast;
  std::unique_ptr<Sampler> m_sampler;
  std::unique_ptr<Optimizer> m_optimizer;
  std::unique_ptr<LightCacheBuilder> m_cache;  ///< null: no light cache
};

} // namespace hilight
