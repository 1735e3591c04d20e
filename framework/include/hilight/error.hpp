#pragma once
/// Errors that reach the user. An InputError is the user's fault (bad file,
/// bad option): the launcher prints its one line and exits with code 2.
#include <stdexcept>
#include <string>

namespace hilight {

/// Bad input from the user: a file, an option, a request that cannot be met.
class InputError : public std::runtime_error {
public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  /// "<file>: <problem>", the form every file-related error takes.
  InputError(const std::string& file, const std::string& problem)
      : std::runtime_error(file + ": " + problem) {}
};

constexpr int kExitInputError = 2;

} // namespace hilight
