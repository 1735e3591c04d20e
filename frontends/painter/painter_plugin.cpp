// The `painter` frontend module: owns the launcher's `paint` command.
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"
#include "paint_command.hpp"

namespace hilight::painter {

namespace {

class PainterFrontend final : public Frontend {
public:
  std::vector<CommandInfo> commands() const override {
    return {{"paint", "paint the wanted illumination onto a scene in a window; find the lights"}};
  }
  int run(const std::string& command, const std::vector<std::string>& args, Registry& registry) override {
    return command == "paint" ? run_paint(args, registry) : 2;
  }
};

void register_painter(PluginRegistrar& registrar) {
  registrar.frontend([] { return std::make_unique<PainterFrontend>(); });
}

} // namespace
} // namespace hilight::painter

HILIGHT_PLUGIN("frontend", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "the painter: paint illumination in a window (GLFW + ImGui), find the lights",
               hilight::painter::register_painter)
