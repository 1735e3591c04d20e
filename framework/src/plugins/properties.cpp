#include "hilight/properties.hpp"

#include "hilight/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace hilight {

Properties Properties::from_assignments(const std::vector<std::string>& items) {
  Properties props;
  for (const auto& item : items) {
    auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("option '" + item + "' is not of the form key=value");
    props.set(item.substr(0, eq), item.substr(eq + 1));
  }
  return props;
}

std::string Properties::get_string(const std::string& key, const std::string& fallback) const {
  m_queried.insert(key);
  auto it = m_values.find(key);
  return it == m_values.end() ? fallback : it->second;
}

long long Properties::get_int(const std::string& key, long long fallback) const {
  m_queried.insert(key);
  auto it = m_values.find(key);
  if (it == m_values.end()) return fallback;
  char* end = nullptr;
  errno = 0;
  long long v = std::strtoll(it->second.c_str(), &end, 10);
  if (it->second.empty() || *end != '\0') throw InputError("option " + key + "=" + it->second + " is not an integer");
  if (errno == ERANGE) throw InputError("option " + key + "=" + it->second + " is out of range");
  return v;
}

double Properties::get_double(const std::string& key, double fallback) const {
  m_queried.insert(key);
  auto it = m_values.find(key);
  if (it == m_values.end()) return fallback;
  char* end = nullptr;
  double v = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || !std::isfinite(v))
    throw InputError("option " + key + "=" + it->second + " is not a finite number");
  return v;
}

bool Properties::get_bool(const std::string& key, bool fallback) const {
  m_queried.insert(key);
  auto it = m_values.find(key);
  if (it == m_values.end()) return fallback;
  const auto& v = it->second;
  if (v == "1" || v == "true" || v == "on" || v == "yes") return true;
  if (v == "0" || v == "false" || v == "off" || v == "no") return false;
  throw InputError("option " + key + "=" + v + " is not a boolean");
}

std::vector<std::string> Properties::unqueried() const {
  std::vector<std::string> out;
  for (const auto& [key, value] : m_values)
    if (!m_queried.count(key)) out.push_back(key);
  return out;
}

void Properties::expect_all_queried(const std::string& owner) const {
  auto unread = unqueried();
  if (!unread.empty()) throw InputError(owner + ": unknown option '" + unread.front() + "'");
}

} // namespace hilight
