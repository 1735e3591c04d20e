#include "hilight/registry.hpp"

#include "hilight/error.hpp"
#include "hilight/plugin.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <sstream>

namespace hilight {

namespace fs = std::filesystem;

void PluginRegistrar::renderer(RendererFactory create, ProbeFunction probe, ProbeFunction detail) {
  if (m_record.kind != "renderer") throw std::logic_error("module " + m_record.name + " registers a renderer but says it is a " + m_record.kind);
  m_record.create_renderer = std::move(create);
  m_record.probe = std::move(probe);
  m_record.detail = std::move(detail);
}

void PluginRegistrar::renderer_traits(RendererTraits traits) {
  if (m_record.kind != "renderer") throw std::logic_error("module " + m_record.name + " declares renderer traits but says it is a " + m_record.kind);
  m_record.renderer_traits = std::move(traits);
}

void PluginRegistrar::frontend(FrontendFactory create) {
  if (m_record.kind != "frontend") throw std::logic_error("module " + m_record.name + " registers a frontend but says it is a " + m_record.kind);
  m_record.create_frontend = std::move(create);
}

void PluginRegistrar::optimizer(OptimizerFactory create) {
  if (m_record.kind != "optimizer") throw std::logic_error("module " + m_record.name + " registers an optimizer but says it is a " + m_record.kind);
  m_record.create_optimizer = std::move(create);
}

void PluginRegistrar::sampler(SamplerFactory create) {
  if (m_record.kind != "sampler") throw std::logic_error("module " + m_record.name + " registers a sampler but says it is a " + m_record.kind);
  m_record.create_sampler = std::move(create);
}

void PluginRegistrar::cache(CacheFactory create) {
  if (m_record.kind != "cache") throw std::logic_error("module " + m_record.name + " registers a light cache but says it is a " + m_record.kind);
  m_record.create_cache = std::move(create);
}

fs::path Registry::user_plugin_dir() {
  const char* data = std::getenv("XDG_DATA_HOME");
  if (data && *data == '/') return fs::path(data) / "hilight" / "plugins";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".local" / "share" / "hilight" / "plugins";
  return {};
}

std::vector<PluginDir> Registry::default_search_dirs(const fs::path& executable) {
  std::vector<PluginDir> dirs;
  if (const char* env = std::getenv("HILIGHT_PLUGIN_PATH")) {
    std::stringstream ss(env);
    std::string item;
    while (std::getline(ss, item, ':'))
      if (!item.empty()) dirs.push_back({item, "HILIGHT_PLUGIN_PATH"});
  }
  if (fs::path user = user_plugin_dir(); !user.empty()) dirs.push_back({user, "user folder"});
  std::error_code ec;
  fs::path exe = fs::weakly_canonical(executable, ec);
  if (!ec) dirs.push_back({exe.parent_path().parent_path() / "lib" / "hilight", "installed"});
  return dirs;
}

void Registry::load_directory(const fs::path& dir, const std::string& origin) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    auto name = entry.path().filename().string();
    if (name.rfind("hilight-", 0) == 0 && entry.path().extension() == ".so") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) load_module(f, origin);
}

std::vector<const ModuleRecord*> Registry::shadowed() const {
  std::vector<const ModuleRecord*> out;
  for (const auto& m : m_modules)
    if (!m->shadowed_by.empty()) out.push_back(m.get());
  return out;
}

const ModuleRecord& Registry::load_module(const fs::path& file, const std::string& origin) {
  auto record = std::make_unique<ModuleRecord>();
  record->path = file;
  record->origin = origin;
  record->name = file.stem().string();
  auto fail = [&](const std::string& why) -> const ModuleRecord& {
    record->problem = why;
    m_modules.push_back(std::move(record));
    return *m_modules.back();
  };

  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* err = dlerror();
    return fail(std::string("cannot load: ") + (err ? err : "unknown dlopen error"));
  }
  auto entry_fn = reinterpret_cast<HilightPluginEntryFn>(dlsym(handle, HILIGHT_PLUGIN_ENTRY_SYMBOL));
  if (!entry_fn) return fail("not a hilight plugin: no " HILIGHT_PLUGIN_ENTRY_SYMBOL "() symbol");
  const HilightPluginEntry* entry = entry_fn();
  if (!entry) return fail("entry point returned nothing");
  // Only plain C data is read until both checks pass.
  if (entry->abi_version != HILIGHT_ABI_VERSION)
    return fail("built against plugin ABI version " + std::to_string(entry->abi_version) + ", this hilight uses version " +
                std::to_string(HILIGHT_ABI_VERSION) + "; rebuild the module");
  if (!entry->build_key || std::strcmp(entry->build_key, HILIGHT_BUILD_KEY) != 0)
    return fail(std::string("built with ") + (entry->build_key ? entry->build_key : "(none)") + ", this hilight with " +
                HILIGHT_BUILD_KEY + "; rebuild the module");
  record->kind = entry->kind ? entry->kind : "";
  record->name = entry->name ? entry->name : record->name;
  record->version = entry->version ? entry->version : "";
  record->description = entry->description ? entry->description : "";
  if (record->kind != "renderer" && record->kind != "frontend" && record->kind != "optimizer" && record->kind != "sampler" &&
      record->kind != "cache")
    return fail("unknown plugin kind '" + record->kind + "'");
  if (const ModuleRecord* other = find(record->kind, record->name)) {
    // Two copies of one file (a folder listed twice) are the same module, not a rival.
    std::error_code ec;
    if (fs::equivalent(other->path, file, ec))
      return fail("duplicate " + record->kind + " '" + record->name + "': the same file was loaded already");
    record->shadowed_by = other->path;
    return fail("shadowed by " + other->path.string() +
                (other->origin.empty() ? std::string() : " (" + other->origin + ")") + ", found first: a duplicate " +
                record->kind + " '" + record->name + "'");
  }
  try {
    PluginRegistrar registrar(*record);
    entry->register_plugin(&registrar);
  } catch (const std::exception& e) {
    return fail(std::string("registration failed: ") + e.what());
  }
  record->loaded = true;
  m_modules.push_back(std::move(record));
  return *m_modules.back();
}

const ModuleRecord* Registry::find(const std::string& kind, const std::string& name) const {
  for (const auto& m : m_modules)
    if (m->loaded && m->kind == kind && m->name == name) return m.get();
  return nullptr;
}

std::vector<std::string> Registry::names(const std::string& kind) const {
  std::vector<std::string> out;
  for (const auto& m : m_modules)
    if (m->loaded && m->kind == kind) out.push_back(m->name);
  return out;
}

const ModuleRecord& Registry::require(const std::string& kind, const std::string& name) const {
  if (const ModuleRecord* m = find(kind, name)) return *m;
  std::string known;
  for (const auto& n : names(kind)) known += (known.empty() ? "" : ", ") + n;
  std::string why;
  for (const auto& m : m_modules)
    if (!m->loaded && m->name.find(name) != std::string::npos) why = " (" + m->path.filename().string() + ": " + m->problem + ")";
  throw InputError("unknown " + kind + " '" + name + "'" + why + "; available: " + (known.empty() ? "none" : known));
}

std::string Registry::renderer_unavailable_reason(const std::string& name) const {
  const ModuleRecord& m = require("renderer", name);
  return m.probe ? m.probe() : std::string();
}

const RendererTraits& Registry::renderer_traits(const std::string& name) const { return require("renderer", name).renderer_traits; }

std::unique_ptr<Renderer> Registry::create_renderer(const std::string& name, const Properties& properties) const {
  const ModuleRecord& m = require("renderer", name);
  if (std::string why = m.probe ? m.probe() : std::string(); !why.empty())
    throw InputError("renderer '" + name + "' is unavailable: " + why);
  auto renderer = m.create_renderer(properties);
  properties.expect_all_queried("renderer " + name);
  return renderer;
}

std::unique_ptr<Optimizer> Registry::create_optimizer(const std::string& name, const Properties& properties) const {
  const ModuleRecord& m = require("optimizer", name);
  auto optimizer = m.create_optimizer(properties);
  properties.expect_all_queried("optimizer " + name);
  return optimizer;
}

std::unique_ptr<Sampler> Registry::create_sampler(const std::string& name, const Properties& properties) const {
  const ModuleRecord& m = require("sampler", name);
  auto sampler = m.create_sampler(properties);
  properties.expect_all_queried("sampler " + name);
  return sampler;
}

std::unique_ptr<LightCacheBuilder> Registry::create_cache(const std::string& name, const Properties& properties) const {
  const ModuleRecord& m = require("cache", name);
  auto cache = m.create_cache(properties);
  properties.expect_all_queried("cache " + name);
  return cache;
}

Frontend* Registry::frontend_for(const std::string& command) {
  for (const auto& m : m_modules) {
    if (!m->loaded || m->kind != "frontend") continue;
    auto it = std::find_if(m_frontends.begin(), m_frontends.end(), [&](const auto& p) { return p.first == m.get(); });
    if (it == m_frontends.end()) {
      m_frontends.emplace_back(m.get(), m->create_frontend());
      it = std::prev(m_frontends.end());
    }
    for (const auto& c : it->second->commands())
      if (c.name == command) return it->second.get();
  }
  return nullptr;
}

std::vector<CommandInfo> Registry::all_commands() {
  std::vector<CommandInfo> out;
  for (const auto& m : m_modules) {
    if (!m->loaded || m->kind != "frontend") continue;
    frontend_for("");  // instantiate every frontend
    break;
  }
  for (const auto& [record, frontend] : m_frontends)
    for (auto& c : frontend->commands()) out.push_back(c);
  return out;
}

} // namespace hilight
