#pragma once
/// Typed configuration handed to a plugin. Every key a plugin reads is marked;
/// keys nobody read are reported as errors so typos surface (Mitsuba's query
/// tracking, pbrt's ReportUnused).
#include <map>
#include <set>
#include <string>
#include <vector>

namespace hilight {

class Properties {
public:
  /// Parses "key=value" items (e.g. from repeated --set options).
  static Properties from_assignments(const std::vector<std::string>& items);

  void set(const std::string& key, const std::string& value) { m_values[key] = value; }
  bool has(const std::string& key) const { return m_values.count(key) != 0; }

  std::string get_string(const std::string& key, const std::string& fallback) const;
  long long get_int(const std::string& key, long long fallback) const;
  double get_double(const std::string& key, double fallback) const;
  bool get_bool(const std::string& key, bool fallback) const;

  /// Keys set but never read by anyone.
  std::vector<std::string> unqueried() const;
  /// Throws InputError naming `owner` and the first unread key.
  void expect_all_queried(const std::string& owner) const;

private:
  std::map<std::string, std::string> m_values;
  mutable std::set<std::string> m_queried;
};

} // namespace hilight
