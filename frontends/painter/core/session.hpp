#pragma once
/// Session scripts: what the painter records of every interactive session and
/// replays with `--script` (docs/painter.md, "Session scripts").
///
///   {"actions": [{"type": "brush", "radius": 0.3, "colour": [1, 0.9, 0.8]},
///                {"type": "stroke", "world": [[0, 0, 0], [0.5, 0, 0]]},
///                {"type": "solve"}, {"type": "save_lights", "path": "lights.json"}]}
///
/// Every action is an object with "type"; parse_session checks each one's
/// fields (names, types, ranges) and rejects unknown ones, so a bad script
/// fails before anything runs, with InputError("<file>: action 3: ...").
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace hilight::painter {

struct Action {
  std::string type;
  nlohmann::json params = nlohmann::json::object();  ///< the action's other fields (null counts as {})

  bool operator==(const Action&) const = default;
};

struct Session {
  std::vector<Action> actions;
  bool operator==(const Session&) const = default;
};

/// Every action type, in the order docs/painter.md lists them.
const std::vector<std::string>& action_types();

/// InputError(source, "action <index>: <problem>") unless `action` is valid.
void validate_action(const Action& action, const std::string& source, size_t index);

Session parse_session(const std::string& text, const std::string& source);
Session read_session(const std::filesystem::path& path);
/// Pretty JSON, one action per line: {"actions": [...]}.
std::string session_to_json(const Session& session);
/// Written through write_atomically.
void write_session(const std::filesystem::path& path, const Session& session);

/// Appends actions as the designer works; save() at any time (a crash report
/// is the file saved so far).
class SessionRecorder {
public:
  /// Validates, then appends. std::logic_error on an invalid action (a bug in the caller).
  void record(Action action);
  const Session& session() const { return m_session; }
  void save(const std::filesystem::path& path) const { write_session(path, m_session); }
  void clear() { m_session.actions.clear(); }

private:
  Session m_session;
};

} // namespace hilight::painter
