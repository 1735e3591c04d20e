#include "hilight/light_space.hpp"

#include "hilight/error.hpp"

#include <cstdlib>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace hilight {

namespace {

std::vector<float> numbers(const std::string& text, const std::string& rule, char separator) {
  std::vector<float> out;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) {
    char* end = nullptr;
    const float v = std::strtof(part.c_str(), &end);
    if (part.empty() || !end || *end != '\0' || !std::isfinite(v)) throw InputError("--place " + rule + ": '" + part + "' is not a number");
    out.push_back(v);
  }
  return out;
}

bool is_number(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

Bounds box_of(const std::string& text, const std::string& rule) {
  const auto v = numbers(text, rule, ',');
  if (v.size() != 6) throw InputError("--place " + rule + ": a box is X0,Y0,Z0,X1,Y1,Z1 (6 numbers)");
  Bounds b;
  b.extend(Vec3(v[0], v[1], v[2]));
  b.extend(Vec3(v[3], v[4], v[5]));
  return b;
}

std::string box_text(const Bounds& b) {
  std::ostringstream s;
  s << b.lo.x << ',' << b.lo.y << ',' << b.lo.z << ',' << b.hi.x << ',' << b.hi.y << ',' << b.hi.z;
  return s.str();
}

} // namespace

bool PlacementRules::any() const {
  return ceiling_offset || std::isfinite(min_height) || std::isfinite(max_height) || !boxes.empty() || !excluded.empty() ||
         min_count || max_count || !regions.empty() || !not_regions.empty() || !region_names.empty() || !not_region_names.empty() ||
         !rooms.empty() || !not_rooms.empty();
}

bool PlacementRules::says_where() const {
  return anywhere || ceiling_offset || std::isfinite(min_height) || std::isfinite(max_height) || !boxes.empty();
}

std::string PlacementRules::describe() const {
  std::ostringstream s;
  if (ceiling_offset) s << "ceiling:" << *ceiling_offset << ' ';
  if (std::isfinite(min_height) || std::isfinite(max_height)) s << "height:" << min_height << ':' << max_height << ' ';
  for (const auto& b : boxes) s << "box:" << box_text(b) << ' ';
  for (const auto& b : excluded) s << "exclude:" << box_text(b) << ' ';
  if (min_count || max_count) s << "count:" << min_count << ':' << max_count << ' ';
  for (int r : regions) s << "region:" << r << ' ';
  for (int r : not_regions) s << "not-region:" << r << ' ';
  for (const auto& n : region_names) s << "region:" << n << ' ';
  for (const auto& n : not_region_names) s << "not-region:" << n << ' ';
  for (const auto& r : rooms) s << "region:" << r.name << ' ';
  for (const auto& r : not_rooms) s << "not-region:" << r.name << ' ';
  std::string out = s.str();
  if (!out.empty()) out.pop_back();
  return out;
}

void PlacementRules::add(const std::string& rule) {
  const auto colon = rule.find(':');
  const std::string kind = rule.substr(0, colon), rest = colon == std::string::npos ? "" : rule.substr(colon + 1);
  if (kind == "ceiling") {
    const float offset = rest.empty() ? 0.2f : numbers(rest, rule, ':').at(0);
    if (!(offset > 0.f)) throw InputError("--place " + rule + ": the offset below the ceiling must be > 0");
    ceiling_offset = offset;
  } else if (kind == "height") {
    const auto v = numbers(rest, rule, ':');
    if (v.size() != 2 || !(v[0] <= v[1])) throw InputError("--place " + rule + ": write height:MIN:MAX with MIN <= MAX");
    min_height = v[0], max_height = v[1];
  } else if (kind == "box") {
    boxes.push_back(box_of(rest, rule));
  } else if (kind == "exclude") {
    excluded.push_back(box_of(rest, rule));
  } else if (kind == "anywhere" && colon == std::string::npos) {
    anywhere = true;
  } else if ((kind == "region" || kind == "not-region") && !rest.empty() && !is_number(rest)) {  // a room's or storey's name ('0. Erdgeschoss')
    (kind == "region" ? region_names : not_region_names).push_back(rest);
  } else if (kind == "region" || kind == "not-region") {
    const auto v = numbers(rest, rule, ':');
    if (v.size() != 1 || v[0] < 0.f || v[0] > 1e6f || v[0] != std::floor(v[0]))
      throw InputError("--place " + rule + ": write " + kind + ":K with K a region number from `hilight info`");
    (kind == "region" ? regions : not_regions).push_back(int(v[0]));
  } else if (kind == "count") {
    const auto v = numbers(rest, rule, ':');
    const bool whole = std::all_of(v.begin(), v.end(), [](float x) { return x >= 1.f && x <= 1e4f && x == std::floor(x); });
    if (v.empty() || v.size() > 2 || !whole || v.front() > v.back())
      throw InputError("--place " + rule + ": write count:MIN:MAX or count:N (whole numbers from 1, MIN <= MAX)");
    min_count = size_t(v.front()), max_count = size_t(v.back());
  } else {
    throw InputError("--place " + rule + ": unknown rule (ceiling[:OFFSET], height:MIN:MAX, box:X0,Y0,Z0,X1,Y1,Z1, exclude:..., count:MIN:MAX, region:K or region:NAME, not-region:K, anywhere)");
  }
}

void PlacementRules::resolve_room_names(const std::vector<NamedRoom>& scene_rooms) {
  for (auto [names, into] : {std::pair{&region_names, &rooms}, std::pair{&not_region_names, &not_rooms}}) {
    for (const auto& name : *names) {
      const auto found = rooms_named(scene_rooms, name);
      if (found.empty()) {
        std::string known;
        for (const auto& r : scene_rooms) known += (known.empty() ? "" : ", ") + r.name;
        throw InputError("--place " + std::string(into == &rooms ? "region:" : "not-region:") + name + ": no room or storey is named " + name +
                         (scene_rooms.empty() ? " (the scene names no rooms: region:K takes the numbers hilight info lists)"
                                              : " (the scene's rooms: " + known + ")"));
      }
      for (const NamedRoom* r : found) into->push_back(*r);
    }
    names->clear();
  }
}

LightSpace::LightSpace(const RayScene& rays, PlacementRules rules, std::optional<Bounds> light_bounds,
                       std::shared_ptr<const Regions> regions)
    : m_rays(rays), m_rules(std::move(rules)), m_regions(regions ? std::move(regions) : std::make_shared<const Regions>(rays)), m_light_bounds(light_bounds ? *light_bounds : rays.scene().light_bounds()), m_bounds(m_light_bounds) {
  m_bounds.lo.y = std::max(m_bounds.lo.y, m_rules.min_height);
  m_bounds.hi.y = std::min(m_bounds.hi.y, m_rules.max_height);
  if (!m_rules.boxes.empty()) {
    Bounds allowed;
    for (const auto& b : m_rules.boxes) allowed.extend(b.lo), allowed.extend(b.hi);
    m_bounds.lo = glm::max(m_bounds.lo, allowed.lo);
    m_bounds.hi = glm::min(m_bounds.hi, allowed.hi);
  }
  const auto& rooms = m_regions->list();
  for (const auto& [kind, ids] : {std::pair{"region", &m_rules.regions}, std::pair{"not-region", &m_rules.not_regions}})
    for (int r : *ids)
      if (size_t(r) >= rooms.size())
        throw InputError(std::string("--place ") + kind + ":" + std::to_string(r) + ": the scene has " + std::to_string(rooms.size()) +
                         " regions (hilight info lists them)");
  if (!m_rules.regions.empty()) {  // spread candidates over the allowed regions only
    Bounds allowed;
    for (int r : m_rules.regions) allowed.extend(rooms[size_t(r)].box.lo), allowed.extend(rooms[size_t(r)].box.hi);
    m_bounds.lo = glm::max(m_bounds.lo, allowed.lo);
    m_bounds.hi = glm::min(m_bounds.hi, allowed.hi);
  }
  if (!m_rules.region_names.empty() || !m_rules.not_region_names.empty()) {
    PlacementRules unresolved = m_rules;
    unresolved.resolve_room_names({});  // throws, naming the first
  }
  if (!m_rules.rooms.empty()) {  // spread candidates over the named rooms only
    Bounds allowed;
    for (const auto& r : m_rules.rooms) allowed.extend(r.box.lo), allowed.extend(r.box.hi);
    m_bounds.lo = glm::max(m_bounds.lo, allowed.lo);
    m_bounds.hi = glm::min(m_bounds.hi, allowed.hi);
  }
  if (m_rules.ceiling_offset) {  // lights move up to the ceilings: spread candidates over the whole height
    m_bounds.lo.y = m_light_bounds.lo.y;
    m_bounds.hi.y = m_light_bounds.hi.y;
  }
}

bool LightSpace::satisfies_boxes_and_height(const Vec3& p) const {
  if (p.y < m_rules.min_height || p.y > m_rules.max_height) return false;
  for (const auto& b : m_rules.excluded)
    if (b.contains(p)) return false;
  if (!m_rules.regions.empty() || !m_rules.not_regions.empty()) {
    const int region = m_regions->at(p);
    for (int r : m_rules.not_regions)
      if (region == r) return false;
    if (!m_rules.regions.empty() && std::find(m_rules.regions.begin(), m_rules.regions.end(), region) == m_rules.regions.end()) return false;
  }
  for (const auto& r : m_rules.not_rooms)
    if (r.contains(p)) return false;
  if (!m_rules.rooms.empty() &&
      std::none_of(m_rules.rooms.begin(), m_rules.rooms.end(), [&](const NamedRoom& r) { return r.contains(p); }))
    return false;
  if (m_rules.boxes.empty()) return true;
  for (const auto& b : m_rules.boxes)
    if (b.contains(p)) return true;
  return false;
}

std::optional<Vec3> LightSpace::place(const Vec3& p) const {
  if (!is_finite(p)) return std::nullopt;
  if (!m_rules.ceiling_offset) return p;
  // The ceiling: the first surface straight above that faces down and stands
  // a room's height above the floor under `p` (the underside of a table or a
  // shelf does not count: the walk goes on through it).
  const Vec3 up(0.f, 1.f, 0.f);
  const Hit down = m_rays.intersect(p, -up);
  const float floor_y = down.valid() ? p.y - down.t : m_light_bounds.lo.y;
  const float room_height = 0.25f * m_rays.scene().bounds.extent().y;
  Vec3 from = p;
  for (int crossing = 0; crossing < 16; ++crossing) {
    const Hit hit = m_rays.intersect(from, up);
    if (!hit.valid()) return std::nullopt;  // open above: no ceiling
    const float y = from.y + hit.t;
    if (m_rays.face_normals()[hit.triangle].y < -0.5f && y - floor_y >= room_height)
      return Vec3(p.x, y - *m_rules.ceiling_offset, p.z);
    from = Vec3(p.x, y + m_rays.epsilon(), p.z);
  }
  return std::nullopt;
}

float LightSpace::clearance(float wanted) const {
  return m_rules.ceiling_offset ? std::min(wanted, 0.5f * *m_rules.ceiling_offset) : wanted;
}

bool LightSpace::admissible(const Vec3& p) const {
  return is_finite(p) && m_light_bounds.contains(p) && satisfies_boxes_and_height(p) && !m_rays.inside_solid(p);
}

} // namespace hilight
