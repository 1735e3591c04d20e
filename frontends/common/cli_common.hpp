#pragma once
/// Helpers shared by the CLI's commands: argument parsing with CLI11, the
/// scene/renderer options every command takes, and output-path checks.
#include "cli_arguments.hpp"
#include "hilight/bounces.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/registry.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hilight::cli {

using hilight::parse_arguments;

/// The help group of what few users need: the paper's parameters, plugins
/// and their tuning (listed after the options a user needs).
inline constexpr const char* kAdvanced = "Advanced (tuning, plugins)";
/// The same for solve: the paper's parameters are there too.
inline constexpr const char* kSolveAdvanced = "Advanced (the paper's parameters, plugins and tuning; docs/solve.md)";

/// Renderer choice and its settings, as every rendering command takes them.
struct RendererOptions {
  std::string name = PluginDefaults::renderer;
  std::string bounces = "all";  ///< "all" or a count (hilight/bounces.hpp)
  int bounce_samples = 0;  ///< 0: the renderer's default
  std::vector<std::string> settings;  ///< --set key=value, passed through
  int threads = 0;

  /// `tuning_group`: the help group of --bounce-samples and --set; empty:
  /// the command's main options.
  void add_to(CLI::App& app, const std::string& tuning_group = "");
  /// --bounces as a count, or kAllBounces.
  int bounce_count() const { return parse_bounces(bounces, "--bounces"); }
  /// --set's settings with --bounces and --bounce-samples (which win); with
  /// a registry, --bounces within what the renderer carries (bounces_for).
  std::vector<std::string> assignments(const Registry* registry = nullptr) const;
  /// --bounces for the renderer: "all" lowered to RendererTraits::max_bounces;
  /// a count above it is an InputError.
  std::string bounces_for(const Registry& registry) const;
  /// Says on stderr when bounces_for lowered "all".
  void note_bounces(const Registry& registry) const;
  /// Creates and binds the renderer; InputError for unknown/unavailable ones.
  std::unique_ptr<Renderer> create(const Registry& registry, std::shared_ptr<const Scene> scene) const;
};

/// An output's type is its extension: one not in `known` (".json", ...) is
/// an InputError naming the file and what is understood (`advice`). A name
/// without one (a device, `/dev/stdout`, a pipe) is let through.
void check_output_type(const std::string& path, const std::vector<std::string>& known, const std::string& advice);

/// --unit, --max-edge and --max-vertices: how a command loads its scene
/// (the last two in `tuning_group` when one is given).
void add_scene_options(CLI::App& app, SceneLoadOptions& options, const std::string& tuning_group = "");

/// CLI11 validator: a finite number ≥ 0 (NonNegativeNumber lets NaN through).
extern const CLI::Validator FiniteNonNegative;
/// CLI11 validator: "all" or a bounce count 0..1000 (hilight/bounces.hpp).
extern const CLI::Validator BounceCount;


} // namespace hilight::cli
