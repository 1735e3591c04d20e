#include "core/session.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hilight::painter {

using json = nlohmann::json;

Session parse_session(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {  // a syntax error, or a number beyond a double (1e400; found by fuzzing)
    std::string what = e.what();
    throw InputError(source, "not valid JSON (" + what.substr(what.find(']') + 2) + ")");
  }
  if (!doc.is_object() || !doc.contains("actions") || !doc["actions"].is_array())
    throw InputError(source, "a session is a JSON object {\"actions\": [...]}");
  for (const auto& [key, value] : doc.items()) {
    (void)value;
    if (key != "actions") throw InputError(source, "unknown field '" + key + "' (a session has only \"actions\")");
  }
  Session session;
  const json& actions = doc["actions"];
  for (size_t i = 0; i < actions.size(); ++i) {
    const json& a = actions[i];
    if (!a.is_object()) throw InputError(source, "action " + std::to_string(i) + ": must be an object with \"type\"");
    if (!a.contains("type") || !a["type"].is_string())
      throw InputError(source, "action " + std::to_string(i) + ": missing \"type\" (a string)");
    Action action;
    action.type = a["type"].get<std::string>();
    for (const auto& [key, value] : a.items())
      if (key != "type") action.params[key] = value;
    validate_action(action, source, i);
    session.actions.push_back(std::move(action));
  }
  return session;
}

Session read_session(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_session(ss.str(), path.string());
}

std::string session_to_json(const Session& session) {
  std::string text = "{\"actions\": [";
  for (size_t i = 0; i < session.actions.size(); ++i) {
    json a = json::object();
    a["type"] = session.actions[i].type;
    for (const auto& [key, value] : session.actions[i].params.items()) a[key] = value;
    text += (i ? ",\n  " : "\n  ") + a.dump();
  }
  text += session.actions.empty() ? "]}\n" : "\n]}\n";
  return text;
}

void write_session(const std::filesystem::path& path, const Session& session) {
  const std::string text = session_to_json(session);
  write_atomically(path, text);
}

void SessionRecorder::record(Action action) {
  try {
    validate_action(action, "recorded session", m_session.actions.size());
  } catch (const InputError& e) {
    throw std::logic_error(e.what());
  }
  m_session.actions.push_back(std::move(action));
}

} // namespace hilight::painter
