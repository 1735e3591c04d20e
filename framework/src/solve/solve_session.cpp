#include "hilight/solve/solve_session.hpp"

#include "hilight/solve/solve_renderers.hpp"

#include "hilight/bounces.hpp"
#include "hilight/error.hpp"

#include <algorithm>

namespace hilight {

void SolveSession::check_names(const Registry& registry, const SolveSpec& spec) {
  registry.renderer_unavailable_reason(spec.renderer);  // throws for an unknown one
  if (!registry.find("optimizer", spec.optimizer)) registry.create_optimizer(spec.optimizer, {});  // throws naming the known ones
  if (!registry.find("sampler", spec.sampler)) registry.create_sampler(spec.sampler, {});
  if (spec.cache != PluginDefaults::no_cache && !registry.find("cache", spec.cache)) registry.create_cache(spec.cache, {});
  if (spec.cache == PluginDefaults::no_cache && !spec.cache_settings.empty())
    throw InputError("cache settings given with no light cache (--cache " + spec.cache + ")");
}

SolveSession::SolveSession(const Registry& registry, SolveSpec spec, std::shared_ptr<const Scene> scene,
                           std::shared_ptr<const RayScene> rays)
    : m_registry(registry), m_spec(std::move(spec)), m_scene(std::move(scene)), m_rays(std::move(rays)) {
  m_optimizer = registry.create_optimizer(m_spec.optimizer, Properties::from_assignments(m_spec.optimizer_settings));
  m_sampler = registry.create_sampler(m_spec.sampler, Properties::from_assignments(m_spec.sampler_settings));
  check_names(registry, m_spec);
  // D̄ is measured with the renderer as the user set it up (as `hilight
  // render` uses it); thousands of light positions are evaluated with its
  // fast twin, whose cheaper settings the plugin declares.
  m_reference_settings = reference_renderer_settings(m_spec.renderer_settings, m_spec.settings.seed);
  m_fast_settings = fast_renderer_settings(registry.renderer_traits(m_spec.renderer), m_reference_settings);
  // Direct light only: there is no bounce for a light cache to keep.
  const bool bounced = bounces_property(Properties::from_assignments(m_reference_settings), 1, "renderer " + m_spec.renderer) != 0;
  if (m_spec.cache != PluginDefaults::no_cache && bounced)
    m_cache = registry.create_cache(m_spec.cache, Properties::from_assignments(m_spec.cache_settings));
  m_reference = make_renderer(m_reference_settings);
  if (!m_rays) m_rays = RayScene::shared(m_scene);
}

std::unique_ptr<Renderer> SolveSession::make_renderer(const std::vector<std::string>& settings) const {
  auto renderer = m_registry.create_renderer(m_spec.renderer, Properties::from_assignments(settings));
  renderer->set_scene(m_scene);
  return renderer;
}

std::vector<std::string> SolveSession::preview_settings() const {
  const RendererTraits& traits = m_registry.renderer_traits(m_spec.renderer);
  if (traits.preview.empty()) return {};
  for (const auto& kv : m_spec.renderer_settings) {
    auto same_key = [&](const std::string& d) { return setting_key(d) == setting_key(kv); };
    if (std::any_of(traits.preview.begin(), traits.preview.end(), same_key) ||
        std::any_of(traits.fast_twin.begin(), traits.fast_twin.end(), same_key))
      return {};  // the user tuned what the preview would change: show only the exact render
  }
  std::vector<std::string> settings = m_fast_settings;
  for (const auto& kv : traits.preview) {
    std::erase_if(settings, [&](const std::string& s) { return setting_key(s) == setting_key(kv); });
    settings.push_back(kv);
  }
  return settings;
}

Renderer& SolveSession::fast() const {
  std::call_once(m_fast_once, [&] { m_fast = make_renderer(m_fast_settings); });
  return *m_fast;
}

std::unique_ptr<Solver> SolveSession::make_solver(const SolveSettings& settings, ProgressFn progress) const {
  return std::make_unique<Solver>(m_scene, m_rays, fast(), *m_reference, *m_sampler, *m_optimizer, m_cache.get(), settings,
                                  std::move(progress));
}

} // namespace hilight
