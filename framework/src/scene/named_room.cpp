#include "hilight/named_room.hpp"

#include "hilight/room_split.hpp"

#include <algorithm>
#include <cctype>

namespace hilight {

bool NamedRoom::contains(const Vec3& p) const {
  if (split) return split->at(p) == split_number;
  if (!(p.y >= y0 && p.y <= y1) || footprint.size() < 3) return false;
  bool in = false;  // even-odd crossings of a ray along +x
  for (size_t i = 0, j = footprint.size() - 1; i < footprint.size(); j = i++) {
    const glm::vec2 a = footprint[i], b = footprint[j];
    if ((a.y > p.z) != (b.y > p.z) && p.x < (b.x - a.x) * (p.z - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

void NamedRoom::update_box() {
  box = Bounds{};
  for (const auto& c : footprint) {
    box.extend(Vec3(c.x, y0, c.y));
    box.extend(Vec3(c.x, y1, c.y));
  }
}

std::vector<NamedRoom> named_rooms(const std::shared_ptr<const RoomSplit>& split) {
  std::vector<NamedRoom> out;
  for (const auto& r : split->list()) {
    NamedRoom room;
    room.name = "room" + std::to_string(r.number);
    room.number = std::to_string(r.number);
    room.box = r.box;
    room.y0 = r.box.lo.y, room.y1 = r.box.hi.y;
    room.split = split;
    room.split_number = r.number;
    out.push_back(std::move(room));
  }
  return out;
}

namespace {

bool same_ignoring_case(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

} // namespace

std::vector<const NamedRoom*> rooms_named(const std::vector<NamedRoom>& rooms, const std::string& name) {
  for (const auto& equal : {+[](const std::string& a, const std::string& b) { return a == b; }, +same_ignoring_case}) {
    std::vector<const NamedRoom*> out;
    for (const auto& r : rooms)
      if (equal(r.name, name)) out.push_back(&r);
    if (out.empty())
      for (const auto& r : rooms)
        if (!r.storey.empty() && equal(r.storey, name)) out.push_back(&r);
    if (!out.empty()) return out;
  }
  return {};
}

} // namespace hilight
