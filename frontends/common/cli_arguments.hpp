#pragma once
/// Argument parsing shared by the frontend modules that use CLI11 (the CLI's
/// commands and `hilight paint`): one behaviour for --help and bad arguments.
#include "hilight/bounces.hpp"
#include "hilight/edit_distance.hpp"
#include "hilight/error.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace hilight {

/// The option of `app` nearest to `given` ("--lihgts" -> "--lights"), or ""
/// when none is near enough to be what was meant.
inline std::string nearest_option(const CLI::App& app, const std::string& given) {
  std::string best;
  size_t best_distance = std::string::npos;
  const std::string bare = given.substr(given.find_first_not_of('-'));
  for (const CLI::Option* opt : app.get_options()) {
    for (const auto& name : opt->get_lnames()) {
      const size_t d = edit_distance(bare, name);
      if (d < best_distance) best_distance = d, best = "--" + name;
    }
  }
  // Near: a slip of a key or two, fewer the shorter the name.
  const size_t allowed = std::max<size_t>(1, std::min<size_t>(3, bare.size() / 3));
  return best_distance <= allowed ? best : std::string();
}

/// The first argument CLI11 could not place that looks like an option
/// ("--lihgts", "-x"; not a negative number), or "".
inline std::string unknown_option(const CLI::App& app) {
  for (const auto& arg : app.remaining()) {
    const std::string name = arg.substr(0, arg.find('='));
    const bool long_form = name.size() > 2 && name.compare(0, 2, "--") == 0;
    const bool short_form = name.size() == 2 && name[0] == '-' && std::isalpha(static_cast<unsigned char>(name[1]));
    if (long_form || short_form) return name;
  }
  return "";
}

/// The exit codes, for the end of a command's --help (`with_unmet`: 3 is
/// one of them). parse_arguments puts the plain list under a help that has
/// no footer of its own.
inline std::string exit_codes_help(bool with_unmet = false) {
  std::string out = "Exit codes: 0 done; 2 bad input (one line on stderr says what; no output is written)";
  if (with_unmet) out += "; 3 the result misses what was asked (--max-dbar, criteria not met; its files are still written)";
  return out + "; 130 interrupted (Ctrl-C; no half-written file is left); 1 an internal error (a bug: please report it).";
}

/// Parses `args` into `app`. Returns an exit code when the command should
/// stop here (--help printed: 0), nullopt to go on; bad arguments throw
/// InputError prefixed with the command's name.
inline std::optional<int> parse_arguments(CLI::App& app, const std::vector<std::string>& args) {
  if (app.get_footer().empty()) app.footer(exit_codes_help());
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them back to front
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    // An option misspelled is said first (before "--target is required",
    // which it may be the cause of), with the one that was probably meant.
    if (const std::string unknown = unknown_option(app); !unknown.empty()) {
      const std::string meant = nearest_option(app, unknown);
      throw InputError(app.get_name() + ": unknown option " + unknown +
                       (meant.empty() ? " (" + app.get_name() + " --help lists the options)" : "; did you mean " + meant + "?"));
    }
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
