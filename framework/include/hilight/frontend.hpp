#pragma once
/// A frontend module owns some of the launcher's subcommands (the CLI owns
/// render/info/plugins/bench/..., the painter owns paint).
#include <string>
#include <vector>

namespace hilight {

class Registry;

struct CommandInfo {
  std::string name;
  std::string summary;
};

class Frontend {
public:
  virtual ~Frontend() = default;
  virtual std::vector<CommandInfo> commands() const = 0;
  /// Runs `command` with its arguments (program name excluded). Returns the
  /// exit code; InputError escapes to the launcher, which prints it.
  virtual int run(const std::string& command, const std::vector<std::string>& args, Registry& registry) = 0;
};

} // namespace hilight
