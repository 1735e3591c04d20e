// The `cli` frontend module: the command-line subcommands of `hilight`.
#include "commands.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"

namespace hilight::cli {

namespace {

class CliFrontend final : public Frontend {
public:
  std::vector<CommandInfo> commands() const override {
    return {{"info", "print a scene's size, bounds and tessellation"},
            {"render", "illuminate a scene with lights: PLY per vertex, PNG/EXR image"},
            {"solve", "find the lights that produce a target illumination"},
            {"export", "write the scene and lights for POV-Ray (.pov) or glTF tools (.gltf/.glb)"},
            {"target", "make illuminance criteria (a lux work plane, walls, ceiling) to solve for"},
            {"luminaire", "read an IES LM-63 or EULUMDAT file: its flux, peak, symmetry (JSON)"},
            {"plugins", "list plugin modules, their versions and availability"},
            {"cache", "list or clear the light caches kept between solves"}};
  }
  int run(const std::string& command, const std::vector<std::string>& args, Registry& registry) override {
    if (command == "info") return run_info(args);
    if (command == "render") return run_render(args, registry);
    if (command == "solve") return run_solve(args, registry);
    if (command == "export") return run_export(args, registry);
    if (command == "luminaire") return run_luminaire(args);
    if (command == "target") return run_target(args);
    if (command == "plugins") return run_plugins(args, registry);
    if (command == "cache") return run_cache(args);
    return 2;
  }
};

void register_cli(PluginRegistrar& registrar) {
  registrar.frontend([] { return std::make_unique<CliFrontend>(); });
}

} // namespace
} // namespace hilight::cli

HILIGHT_PLUGIN("frontend", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "command-line interface: info, render, solve, export, target, luminaire, plugins, cache",
               hilight::cli::register_cli)
