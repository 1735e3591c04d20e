#pragma once
/// Finds, checks and loads plugin modules, and creates plugins by name.
/// Modules are never unloaded: objects they created may outlive any scope.
#include "hilight/frontend.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/optimizer.hpp"
#include "hilight/properties.hpp"
#include "hilight/renderer.hpp"
#include "hilight/sampler.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hilight {

using RendererFactory = std::function<std::unique_ptr<Renderer>(const Properties&)>;
/// Returns "" when the plugin can run here, else why not (e.g. "no Vulkan device").
using ProbeFunction = std::function<std::string()>;
using FrontendFactory = std::function<std::unique_ptr<Frontend>()>;
using OptimizerFactory = std::function<std::unique_ptr<Optimizer>(const Properties&)>;
using SamplerFactory = std::function<std::unique_ptr<Sampler>(const Properties&)>;
using CacheFactory = std::function<std::unique_ptr<LightCacheBuilder>(const Properties&)>;

/// The plugins a solve uses when the user names none: the one place in the
/// framework that names a backend, an optimizer or a sampler.
struct PluginDefaults {
  static constexpr const char* renderer = "embree";
  static constexpr const char* optimizer = "varpro";
  static constexpr const char* sampler = "importance";
  static constexpr const char* cache = "grid";
  /// Not a plugin: the cache choice that solves without a light cache.
  static constexpr const char* no_cache = "none";
};

/// What a renderer declares about itself at registration, so that the core
/// asks it rather than testing its name. Settings are `key=value`; each one
/// applies unless the caller set that key.
struct RendererTraits {
  /// The solve's fast twin, which evaluates thousands of light positions
  /// (the reference, as the user set it up, measures D̄ and polishes).
  std::vector<std::string> fast_twin;
  /// On top of the fast twin: a quick preview for interactive display (the
  /// painter shows it before the exact render). Empty: no preview stage.
  std::vector<std::string> preview;
  /// Direct light at a solve's samples takes milliseconds, so a solve may
  /// spend hundreds of direct renders settling fine-tune's answer with the
  /// bounce (SolveSettings::settle_fine_tune); false where each is a
  /// process run or a GPU submission (minutes in all).
  bool cheap_direct = false;
  /// The most diffuse bounces it carries (kAllBounces: every one). A
  /// command asked for "all" lowers it to this and says so; a count above
  /// it is refused.
  int max_bounces = -1;
};

struct ModuleRecord {
  std::filesystem::path path;
  std::string origin;  ///< which search folder it came from (PluginDir::origin); "" if loaded by path
  std::string kind, name, version, description;
  bool loaded = false;
  std::string problem;  ///< why it did not load (empty when loaded)
  /// The module of the same kind and name found first, when that is why
  /// this one did not load (empty otherwise).
  std::filesystem::path shadowed_by;

  RendererFactory create_renderer;
  ProbeFunction probe;
  ProbeFunction detail;  ///< extra status text when available (may be empty)
  RendererTraits renderer_traits;
  FrontendFactory create_frontend;
  OptimizerFactory create_optimizer;
  SamplerFactory create_sampler;
  CacheFactory create_cache;
};

/// Handed to a module's register function; binds what it registers to its record.
class PluginRegistrar {
public:
  explicit PluginRegistrar(ModuleRecord& record) : m_record(record) {}
  /// `detail` (optional) says more for `hilight plugins`, e.g. which device a renderer uses.
  void renderer(RendererFactory create, ProbeFunction probe = {}, ProbeFunction detail = {});
  /// Declares the renderer's fast twin and preview settings (RendererTraits).
  void renderer_traits(RendererTraits traits);
  void frontend(FrontendFactory create);
  void optimizer(OptimizerFactory create);
  void sampler(SamplerFactory create);
  void cache(CacheFactory create);

private:
  ModuleRecord& m_record;
};

/// A folder that plugins are loaded from, and what put it on the list.
struct PluginDir {
  std::filesystem::path path;
  std::string origin;  ///< "HILIGHT_PLUGIN_PATH", "user folder" or "installed"
};

class Registry {
public:
  /// Where plugins come from, first to last (docs/plugins.md): every entry of
  /// HILIGHT_PLUGIN_PATH (colon-separated), then the user's folder
  /// ($XDG_DATA_HOME/hilight/plugins, else ~/.local/share/hilight/plugins),
  /// then lib/hilight beside the executable's bin/ (the installed plugins).
  /// The first module of a kind and name wins; a later one is recorded as
  /// shadowed, never loaded.
  static std::vector<PluginDir> default_search_dirs(const std::filesystem::path& executable);
  /// The user's plugin folder (which need not exist); empty without HOME and XDG_DATA_HOME.
  static std::filesystem::path user_plugin_dir();

  /// Loads every hilight-*.so in `dir` (sorted by name, so the order is stable).
  void load_directory(const std::filesystem::path& dir, const std::string& origin = "");
  /// Loads one module; failures are recorded, never thrown.
  const ModuleRecord& load_module(const std::filesystem::path& file, const std::string& origin = "");
  /// Modules that a module of the same kind and name, found first, shadows.
  std::vector<const ModuleRecord*> shadowed() const;

  const std::vector<std::unique_ptr<ModuleRecord>>& modules() const { return m_modules; }
  const ModuleRecord* find(const std::string& kind, const std::string& name) const;
  std::vector<std::string> names(const std::string& kind) const;

  /// Why the renderer cannot run here ("" if it can); throws on an unknown name.
  std::string renderer_unavailable_reason(const std::string& name) const;
  /// What the renderer declared about itself; InputError for an unknown one.
  const RendererTraits& renderer_traits(const std::string& name) const;
  /// Creates a renderer; InputError for an unknown or unavailable one, or an
  /// option it did not read.
  std::unique_ptr<Renderer> create_renderer(const std::string& name, const Properties& properties) const;
  /// Creates an optimizer; InputError for an unknown one or an unread option.
  std::unique_ptr<Optimizer> create_optimizer(const std::string& name, const Properties& properties) const;
  /// Creates a sampler; InputError for an unknown one or an unread option.
  std::unique_ptr<Sampler> create_sampler(const std::string& name, const Properties& properties) const;
  /// Creates a light cache plugin; InputError for an unknown one or an unread option.
  std::unique_ptr<LightCacheBuilder> create_cache(const std::string& name, const Properties& properties) const;

  /// The frontend that owns `command`, created on first use; nullptr if none.
  Frontend* frontend_for(const std::string& command);
  /// All commands of all frontends, for help text.
  std::vector<CommandInfo> all_commands();

private:
  const ModuleRecord& require(const std::string& kind, const std::string& name) const;
  std::vector<std::unique_ptr<ModuleRecord>> m_modules;
  std::vector<std::pair<const ModuleRecord*, std::unique_ptr<Frontend>>> m_frontends;
};

} // namespace hilight
