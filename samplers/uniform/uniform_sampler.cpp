// The `uniform` sampler: target points in proportion to their weight alone
// (tessellation is near-uniform, so this is near-uniform over the surface).
// The baseline the importance sampler is measured against.
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"
#include "hilight/sampler.hpp"

namespace {

class UniformSampler final : public hilight::Sampler {
public:
  hilight::SampleSet draw(const hilight::Target& target, const hilight::SampleRequest& request) override {
    return hilight::draw_by_weight(target, std::vector<double>(target.weight.begin(), target.weight.end()), request.count, request.seed);
  }
};

void register_uniform(hilight::PluginRegistrar& registrar) {
  registrar.sampler([](const hilight::Properties&) { return std::make_unique<UniformSampler>(); });
}

} // namespace

HILIGHT_PLUGIN("sampler", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "target points in proportion to their weight", register_uniform)
