// The `bench` frontend module: `hilight bench`, measurements on the fixture
// scenes (JSON lines). Apart from the `cli` module so that the fixtures ship
// only with it.
#include "bench_commands.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"

namespace hilight::bench {

namespace {

class BenchFrontend final : public Frontend {
public:
  std::vector<CommandInfo> commands() const override {
    return {{"bench", "measure renderer throughput (machine-readable JSON lines)"}};
  }
  int run(const std::string& command, const std::vector<std::string>& args, Registry& registry) override {
    return command == "bench" ? run_bench(args, registry) : 2;
  }
};

void register_bench(PluginRegistrar& registrar) {
  registrar.frontend([] { return std::make_unique<BenchFrontend>(); });
}

} // namespace
} // namespace hilight::bench

HILIGHT_PLUGIN("frontend", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION,
               "benchmarks on the fixture scenes: hilight bench (render, solve, cache, renderers, lux)",
               hilight::bench::register_bench)
