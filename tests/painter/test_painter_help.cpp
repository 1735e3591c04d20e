// `hilight paint --help`: the solve's options are the ones `hilight solve`
// declares (frontends/common/solve_options.hpp), with the painter's defaults.
#include "support.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <regex>
#include <string>

using Catch::Matchers::Contains;

namespace {

/// The help of `option`: its line and its description's (up to the next option).
std::string help_entry(const std::string& help, const std::string& option) {
  const size_t at = help.find("\n  " + option + " ");
  if (at == std::string::npos) return "";
  const size_t next = std::min(help.find("\n  -", at + 1), help.find("\n\n", at + 1));
  return help.substr(at + 1, next - at - 1);
}

/// `entry` without its default ("=1") and with its spaces and line breaks as one space.
std::string without_default(const std::string& entry) {
  return std::regex_replace(std::regex_replace(entry, std::regex(R"(=\S*)"), ""), std::regex(R"(\s+)"), " ");
}

} // namespace

TEST_CASE("paint --help: the solve options are hilight solve's, with the painter's defaults", "[painter][help]") {
  const test::RunResult paint = test::run_hilight({"paint", "--help"});
  const test::RunResult solve = test::run_hilight({"solve", "--help"});
  REQUIRE(paint.exit_code == 0);
  REQUIRE(solve.exit_code == 0);
  // The same flags with the same words (the defaults aside).
  for (const char* option : {"--place", "--renderer", "--bounces", "--bounce-samples", "--set", "--threads", "--optimizer", "--opt",
                             "--sampler", "--samples", "--evaluation-points", "--cache", "--cache-setting", "--cache-cells",
                             "--no-cache", "--cache-dir"}) {
    INFO(option);
    const std::string in_paint = help_entry(paint.out, option), in_solve = help_entry(solve.out, option);
    REQUIRE_FALSE(in_paint.empty());
    REQUIRE_FALSE(in_solve.empty());
    CHECK(without_default(in_paint) == without_default(in_solve));
  }
  // Every --place form, as in hilight solve.
  CHECK_THAT(help_entry(paint.out, "--place"), Contains("region:K") && Contains("count:MIN:MAX"));
  // The painter's defaults: one bounce, D̄ on 256 points.
  CHECK_THAT(help_entry(paint.out, "--bounces"), Contains("0..1000=1\n"));
  CHECK_THAT(help_entry(solve.out, "--bounces"), Contains("0..1000=all\n"));
  CHECK_THAT(help_entry(paint.out, "--evaluation-points"), Contains("]=256\n"));
  // The paper's parameters stay hilight solve's.
  CHECK(paint.out.find("--n-cut") == std::string::npos);
}
