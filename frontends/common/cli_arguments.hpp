#pragma once
/// Argument parsing shared by the frontend modules that use CLI11 (the CLI's
/// commands and `hilight paint`): one behaviour for --help and bad arguments.
#include "hilight/bounces.hpp"
#include "hilight/error.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace hilight {

/// Parses `args` into `app`. Returns an exit code when the command should
/// stop here (--help printed: 0), nullopt to go on; bad arguments throw
/// InputError prefixed with the command's name.
inline std::optional<int> parse_arguments(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them back to front
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    throw InputError(app.get_name() + ": " + e.what());
  }
  return std::nullopt;
}

/// CLI11 validator of --bounces: "all" or a count 0..1000 (hilight/bounces.hpp).
inline CLI::Validator bounce_count_validator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          parse_bounces(text, "--bounces");
        } catch (const InputError& e) {
          return e.what();
        }
        return {};
      },
      "all|0..1000");
}

} // namespace hilight
