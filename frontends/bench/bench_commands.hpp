#pragma once
/// `hilight bench` and its subcommands, one command_bench*.cpp each.
#include "cli_common.hpp"
#include "hilight/registry.hpp"

#include <string>
#include <vector>

namespace hilight::bench {
// The shared command-line helpers (frontends/common) the bench commands use.
using cli::BounceCount;
using cli::FiniteNonNegative;
using cli::parse_arguments;

/// `hilight bench [render|solve|cache|renderers|lux|bounces] ...`: dispatches to the
/// subcommand; without one (or with "render"), renderer throughput.
int run_bench(const std::vector<std::string>& args, Registry& registry);
int run_bench_solve(const std::vector<std::string>& args, Registry& registry);
int run_bench_cache(const std::vector<std::string>& args, Registry& registry);
int run_bench_bounces(const std::vector<std::string>& args, Registry& registry);
int run_bench_lux(const std::vector<std::string>& args, Registry& registry);
int run_bench_renderers(const std::vector<std::string>& args, Registry& registry);
} // namespace hilight::bench
