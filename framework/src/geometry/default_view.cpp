// The views pictures take when none is given (default_view.hpp). The
// enclosed part of free space to look into is one of the scene's regions
// (regions.hpp): one is enclosed when rays from points in it almost never
// leave the scene. A region joins everything a door or a stair opens into (a
// house's whole interior, attic included), so the eyes stand in one room of
// it: the room split at doors (room_split.hpp) cut at the storeys' floors
// (plan_sections), the largest such room holding a light, else the room of
// the main storey (largest_on_main_storey). Inside it, eyes stand at eye
// height over its floors, and each looks where a fan of rays meets the most
// lit surface the farthest away: across the room, toward its lights' pools,
// not into a wall or out of a window.
#include "hilight/default_view.hpp"

#include "hilight/plan_view.hpp"
#include "hilight/regions.hpp"
#include "hilight/room_split.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

constexpr float kEyeHeight = 1.6f;      ///< metres over the floor (or 60% of a lower room's height)
constexpr float kFovDeg = 65.f;         ///< vertical: with 4:3 about 80° across, a room photographer's lens
constexpr float kPitchDeg = -10.f;      ///< a little down: more floor and furniture, less ceiling
constexpr float kMostEscaping = 0.15f;  ///< an enclosed region lets out at most this fraction of rays
constexpr size_t kMostLights = 32;      ///< lights tried for whether a surface is lit
constexpr int kAzimuths = 16;
constexpr float kRoomSample = 0.2f;     ///< metres between the points that measure a region's rooms
constexpr double kLeastRoom = 1.0;      ///< m³: less is a nook (under a stair), no room to stand in

/// `n` directions spread evenly over the sphere (a Fibonacci lattice).
std::vector<Vec3> sphere_directions(int n) {
  std::vector<Vec3> out;
  const float golden = float(kPi) * (3.f - std::sqrt(5.f));
  for (int i = 0; i < n; ++i) {
    const float y = 1.f - 2.f * (float(i) + 0.5f) / float(n), r = std::sqrt(std::max(0.f, 1.f - y * y));
    out.emplace_back(r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i)));
  }
  return out;
}

/// Where eyes may stand: a box and which of its points belong.
struct Space {
  Bounds box;
  std::function<bool(const Vec3&)> holds;
  /// A storey's floor height: eyes stand on it (within kFloorTolerance), not on a stair's steps.
  std::optional<float> floor;
};

Space region_space(const Regions& regions, const Region& region) {
  return {region.box, [&regions, id = region.id](const Vec3& p) { return regions.at(p) == id; }, std::nullopt};
}

/// Points on an even grid over the space's box that lie in the space.
std::vector<Vec3> points_in(const Space& space, glm::ivec3 cells) {
  std::vector<Vec3> out;
  const Vec3 lo = space.box.lo, extent = space.box.extent();
  for (int z = 0; z < cells.z; ++z)
    for (int y = 0; y < cells.y; ++y)
      for (int x = 0; x < cells.x; ++x) {
        const Vec3 p = lo + (Vec3(float(x), float(y), float(z)) + 0.5f) / Vec3(cells) * extent;
        if (space.holds(p)) out.push_back(p);
      }
  return out;
}

/// The fraction of rays from the space's points that meet nothing.
float escaping(const RayScene& rays, const Space& space) {
  std::vector<Vec3> points = points_in(space, {6, 4, 6});
  if (points.size() < 8) points = points_in(space, {16, 8, 16});
  if (points.empty()) return 1.f;
  static const std::vector<Vec3> directions = sphere_directions(32);
  const size_t step = std::max<size_t>(1, points.size() / 24);
  size_t sent = 0, lost = 0;
  for (size_t i = 0; i < points.size(); i += step)
    for (const Vec3& d : directions) {
      ++sent;
      if (!rays.intersect(points[i], d).valid()) ++lost;
    }
  return float(lost) / float(sent);
}

/// The enclosed regions, largest first: big enough to stand in, and rays from them almost never leave the scene.
std::vector<const Region*> enclosed_regions(const RayScene& rays, const Regions& regions) {
  const double scene_volume = [&] {
    const Vec3 e = rays.scene().light_bounds().extent();
    return double(e.x) * e.y * e.z;
  }();
  std::vector<const Region*> out;
  for (const Region& r : regions.list())  // largest first
    if (r.volume >= 0.01 * scene_volume && escaping(rays, region_space(regions, r)) <= kMostEscaping) out.push_back(&r);
  return out;
}

/// The enclosed region holding a light, the largest such; nullptr when none does.
const Region* lit_region(const std::vector<const Region*>& enclosed, const Regions& regions, const Lighting& lights) {
  for (const Region* r : enclosed)
    if (std::any_of(lights.begin(), lights.end(), [&](const Light& l) { return regions.at(l.position) == r->id; })) return r;
  return nullptr;
}

/// A room: a room of the split at doors on one storey, in one region (the
/// split's rooms may reach a little past a closed door's leaf).
struct RoomKey {
  int region = -1, room = 0;  ///< room 0: none
  float floor = 0.f;          ///< the storey's floor height
  auto operator<=>(const RoomKey&) const = default;
};

/// A room's size and place, from points on a grid over its region.
struct RoomExtent {
  size_t points = 0;  ///< its volume in grid cells
  size_t at_eye = 0;  ///< its cells in the grid's layer at eye height over its storey's floor: floor to stand on
  Bounds box;
  bool lit = false;
};
using Rooms = std::map<RoomKey, RoomExtent>;

/// The outside ground the scene shows around `rooms` (its enclosed regions):
/// the median height where rays straight down from above the scene first
/// meet something outside the regions' plans (grown by a wall's thickness)
/// no higher than a metre over the top storey's floor (`top_floor`: not the
/// eaves of a roof), a terrain or site slab; nullopt when too few do (a
/// building modelled alone: nothing around it).
std::optional<float> outside_ground(const RayScene& rays, const std::vector<const Region*>& rooms, float top_floor) {
  constexpr int kGrid = 48;
  constexpr float kWall = 0.5f;
  const Bounds& bounds = rays.scene().bounds;
  const Vec3 extent = bounds.extent();
  std::vector<float> heights;
  int outside = 0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const float x = bounds.lo.x + (float(i) + 0.5f) / kGrid * extent.x, z = bounds.lo.z + (float(j) + 0.5f) / kGrid * extent.z;
      const bool under_a_room = std::any_of(rooms.begin(), rooms.end(), [&](const Region* r) {
        return x > r->box.lo.x - kWall && x < r->box.hi.x + kWall && z > r->box.lo.z - kWall && z < r->box.hi.z + kWall;
      });
      if (under_a_room) continue;
      ++outside;
      const Vec3 from(x, bounds.hi.y + 1.f, z);
      if (const Hit hit = rays.intersect(from, Vec3(0.f, -1.f, 0.f)); hit.valid() && from.y - hit.t <= top_floor + 1.f)
        heights.push_back(from.y - hit.t);
    }
  // Ground under at least a fifth of the plan around the rooms (a few posts or a hedge are no ground).
  if (heights.empty() || 5 * heights.size() < size_t(outside)) return std::nullopt;
  std::nth_element(heights.begin(), heights.begin() + std::ptrdiff_t(heights.size() / 2), heights.end());
  return heights[heights.size() / 2];
}

/// With no light to go by, the room a person opening a building expects: on
/// the storey with the most floor to stand on (at eye height: an attic under
/// a sloping roof has less than its plan), of those within a tenth of it the
/// one at ground level, the room with the most of it. Ground level (`ground`,
/// in hilight's coordinates): the outside ground the scene shows
/// (outside_ground), else the file's elevation 0 (where architects model the
/// ground floor); a basement of the ground floor's plan is below it. The
/// lowest of storeys equally near (the ground floor under an upper one of the
/// same plan, where the model sits far from 0 with no ground around it). By
/// volume, the attic's tall space under the ridge would win. Where no room
/// has floor at eye height (no storeys), the largest. Ties by key (never by
/// threads or addresses).
const Rooms::value_type* largest_on_main_storey(const Rooms& rooms, float ground) {
  std::map<float, size_t> storey_floor_at_eye;
  for (const auto& [key, room] : rooms) storey_floor_at_eye[key.floor] += room.at_eye;
  size_t most = 0;
  for (const auto& [floor, at_eye] : storey_floor_at_eye) most = std::max(most, at_eye);
  const Rooms::value_type* best = nullptr;
  if (most == 0) {
    for (const auto& entry : rooms)
      if (!best || entry.second.points > best->second.points) best = &entry;
    return best;
  }
  // Storeys from the lowest floor up: of those with nearly the most, the one nearest the ground.
  std::optional<float> main;
  float nearest = 0.f;
  for (const auto& [floor, at_eye] : storey_floor_at_eye) {
    if (10 * at_eye < 9 * most) continue;
    const float off = std::abs(floor - ground);
    if (!main || off < nearest - 1e-3f) main = floor, nearest = off;
  }
  for (const auto& entry : rooms)
    if (entry.first.floor == *main &&
        (!best || std::pair(entry.second.at_eye, entry.second.points) > std::pair(best->second.at_eye, best->second.points)))
      best = &entry;
  return best;
}

/// Where eyes may stand in a room, and the region it lies in.
struct ChosenRoom {
  Space space;
  int region = -1;
};

/// The room to look into, in `searched` (the lit region, or with none every
/// enclosed one: a house's rooms behind closed doors are regions of their
/// own, and they count for their storey): the largest room of the split (cut
/// at the storeys' floors) holding a light, else the one of the main storey
/// (largest_on_main_storey); nullopt when the split finds no room there.
std::optional<ChosenRoom> choose_room_in(const RayScene& rays, const Regions& regions, const std::vector<const Region*>& searched,
                                         const Lighting& lights) {
  const auto split = std::make_shared<const RoomSplit>(rays);
  if (split->list().empty() || searched.empty()) return std::nullopt;
  const auto storeys = std::make_shared<const std::vector<PlanSection>>(plan_sections(rays.scene()));
  std::vector<int> ids;
  Bounds box;
  for (const Region* r : searched) {
    ids.push_back(r->id);
    box.extend(r->box.lo);
    box.extend(r->box.hi);
  }
  // The room p stands in; room 0 outside the regions searched or every room of the split.
  const auto key_of = [split, storeys, &regions, ids](const Vec3& p) {
    const int region = regions.at(p);
    if (std::find(ids.begin(), ids.end(), region) == ids.end()) return RoomKey{};
    return RoomKey{region, split->at(p), storey_floor(*storeys, p)};
  };
  // Each room's volume and box, from points on a grid over the regions.
  std::map<RoomKey, RoomExtent> rooms;
  const Vec3 extent = box.extent();
  const float step = std::max(kRoomSample, std::max({extent.x, extent.y, extent.z}) / 80.f);
  glm::ivec3 cells;
  for (int k = 0; k < 3; ++k) cells[k] = std::max(1, int(std::ceil(extent[k] / step)));
  const Vec3 cell = extent / Vec3(cells);
  for (int z = 0; z < cells.z; ++z)
    for (int y = 0; y < cells.y; ++y)
      for (int x = 0; x < cells.x; ++x) {
        const Vec3 p = box.lo + (Vec3(float(x), float(y), float(z)) + 0.5f) * cell;
        const RoomKey key = key_of(p);
        if (key.room == 0) continue;
        RoomExtent& room = rooms[key];
        ++room.points;
        const float over_eye = p.y - (key.floor + kEyeHeight);
        if (!storeys->empty() && over_eye >= -0.5f * cell.y && over_eye < 0.5f * cell.y) ++room.at_eye;
        room.box.extend(p - 0.5f * cell);
        room.box.extend(p + 0.5f * cell);
      }
  // A light's room by the split alone: its finer grid places a lamp in a window's reveal, where the
  // regions' coarser one may see the outside.
  for (const Light& l : lights) {
    const int room = split->at(l.position);
    const float floor = storey_floor(*storeys, l.position);
    for (auto& [key, lit_room] : rooms)
      if (key.room == room && key.floor == floor) lit_room.lit = true;
  }
  const double cell_volume = double(cell.x) * cell.y * cell.z;
  std::erase_if(rooms, [&](const auto& entry) { return double(entry.second.points) * cell_volume < kLeastRoom; });
  const Rooms::value_type* best = nullptr;
  const bool any_lit = std::any_of(rooms.begin(), rooms.end(), [](const auto& entry) { return entry.second.lit; });
  if (any_lit) {
    // The largest lit room; ties by key (never by threads or addresses).
    for (const auto& entry : rooms)
      if (entry.second.lit && (!best || entry.second.points > best->second.points)) best = &entry;
  } else {
    // Ground level: the ground the scene shows around the building, else the file's elevation 0.
    const SceneFrame& frame = rays.scene().frame;
    const float top_floor = storeys->empty() ? box.lo.y : storeys->back().floor;
    const float ground = outside_ground(rays, searched, top_floor).value_or(float((0.0 - frame.origin.y) * frame.scale));
    best = largest_on_main_storey(rooms, ground);
  }
  if (!best) return std::nullopt;
  return ChosenRoom{Space{best->second.box, [key_of, key = best->first](const Vec3& p) { return key_of(p) == key; }, best->first.floor},
                    best->first.region};
}

/// Whether a light reaches the surface at `q` (normal `n`, turned toward the viewer).
bool lit_at(const RayScene& rays, const Lighting& lights, const Vec3& q, const Vec3& n) {
  if (lights.empty()) return true;  // nothing to go by: every surface counts
  const float eps = 4.f * rays.epsilon();
  for (size_t j = 0; j < std::min(lights.size(), kMostLights); ++j) {
    const Vec3 to = lights[j].position - q;
    const float d = glm::length(to);
    if (!(d > eps) || glm::dot(to, n) <= 0.f) continue;
    if (!rays.occluded(q + eps * n, to / d, d - 2.f * eps)) return true;
  }
  return false;
}

struct Candidate {
  Vec3 eye{0.f};
  int azimuth = 0;
  float score = 0.f, reach = 1.f;  ///< reach: the mean distance the view's rays travel
};

Vec3 direction(int azimuth, float pitch_deg) {
  const float a = 2.f * float(kPi) * float(azimuth) / float(kAzimuths), p = pitch_deg * float(kPi) / 180.f;
  return {std::cos(p) * std::sin(a), std::sin(p), std::cos(p) * std::cos(a)};
}

/// How much lit surface a view from `eye` along `azimuth` sees, and how far.
Candidate score_view(const RayScene& rays, const Lighting& lights, const Vec3& eye, int azimuth, float aspect, float far) {
  Camera cam;
  cam.eye = eye;
  cam.target = eye + direction(azimuth, kPitchDeg);
  cam.fov_deg = kFovDeg;
  const Camera::Basis b = cam.basis();
  constexpr int kAcross = 9, kDown = 6;
  Candidate c{eye, azimuth, 0.f, 0.f};
  int hits = 0;
  for (int j = 0; j < kDown; ++j)
    for (int i = 0; i < kAcross; ++i) {
      const float sx = (2.f * (float(i) + 0.5f) / kAcross - 1.f) * b.tan_half_fov * aspect;
      const float sy = (1.f - 2.f * (float(j) + 0.5f) / kDown) * b.tan_half_fov;
      const Vec3 d = glm::normalize(b.forward + sx * b.right + sy * b.up);
      const Hit hit = rays.intersect(eye, d);
      if (!hit.valid()) continue;  // out of a window: nothing to show
      Vec3 n = rays.face_normals()[hit.triangle];
      if (glm::dot(n, d) > 0.f) n = -n;
      const float t = std::min(hit.t, far);
      c.score += lit_at(rays, lights, eye + hit.t * d, n) ? t : 0.05f * t;
      c.reach += t;
      ++hits;
    }
  c.reach = hits ? c.reach / float(hits) : 1.f;
  return c;
}

/// Eyes over the room's floors: each grid point of the room dropped to the
/// floor below it (a room on a storey: that storey's floor) and raised to eye
/// height, kept if still in the room and clear of walls.
std::vector<Vec3> eyes_in(const RayScene& rays, const Space& room, float voxel) {
  std::vector<Vec3> eyes;
  const float clearance = std::max(2.f * voxel, 0.01f * room.box.diagonal());
  for (const Vec3& p : points_in(room, {14, 10, 14})) {
    const Hit down = rays.intersect(p, Vec3(0.f, -1.f, 0.f)), up = rays.intersect(p, Vec3(0.f, 1.f, 0.f));
    if (!down.valid() || std::abs(rays.face_normals()[down.triangle].y) < 0.7f) continue;  // not over a floor
    if (room.floor && std::abs(p.y - down.t - *room.floor) > kFloorTolerance) continue;     // over a step or a table
    const float height = down.t + (up.valid() ? up.t : 1e30f);
    const Vec3 eye(p.x, p.y - down.t + std::min(kEyeHeight, 0.6f * height), p.z);
    if (!room.holds(eye)) continue;
    bool clear = true;
    for (int k = 0; k < 8 && clear; ++k) {
      const float a = float(k) * float(kPi) / 4.f;
      clear = !rays.occluded(eye, Vec3(std::cos(a), 0.f, std::sin(a)), clearance);
    }
    // The grid's layers over one floor give the same eye: keep one.
    const bool again = std::any_of(eyes.begin(), eyes.end(), [&](const Vec3& e) { return glm::length(e - eye) < 0.5f * clearance; });
    if (clear && !again) eyes.push_back(eye);
  }
  return eyes;
}

std::vector<Camera> inside_views(const RayScene& rays, const Space& room, float voxel, const Lighting& lights, float aspect,
                                 size_t count) {
  const std::vector<Vec3> eyes = eyes_in(rays, room, voxel);
  if (eyes.empty()) return {};
  const float far = room.box.diagonal();
  std::vector<Candidate> candidates(eyes.size() * kAzimuths);
  tbb::parallel_for(size_t(0), eyes.size(), [&](size_t e) {
    for (int a = 0; a < kAzimuths; ++a) candidates[e * kAzimuths + size_t(a)] = score_view(rays, lights, eyes[e], a, aspect, far);
  });
  // Best first; ties (a symmetric room) by position, so the choice never depends on threads.
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  std::vector<Candidate> chosen;
  const float apart = 0.25f * glm::length(Vec3(room.box.extent().x, 0.f, room.box.extent().z));
  for (const Candidate& c : candidates) {
    if (chosen.size() == count) break;
    const bool distinct = std::all_of(chosen.begin(), chosen.end(), [&](const Candidate& o) {
      const int turn = std::abs(c.azimuth - o.azimuth) % kAzimuths;
      return glm::length(c.eye - o.eye) > apart || std::min(turn, kAzimuths - turn) >= kAzimuths / 4;
    });
    if (distinct && c.score > 0.f) chosen.push_back(c);
  }
  std::vector<Camera> out;
  for (const Candidate& c : chosen) {
    Camera cam;
    cam.eye = c.eye;
    cam.target = c.eye + c.reach * direction(c.azimuth, kPitchDeg);
    cam.fov_deg = kFovDeg;
    out.push_back(cam);
  }
  return out;
}

std::vector<Camera> outside_views(const Scene& scene, float aspect, size_t count) {
  const Camera base = Camera::framing(scene.bounds, aspect);
  const Vec3 c = scene.bounds.center(), r = base.eye - c;
  std::vector<Camera> out;
  for (size_t k = 0; k < count; ++k) {
    Camera cam = base;
    const float a = float(k) * 2.f * float(kPi) / float(count);
    cam.eye = c + Vec3(r.x * std::cos(a) - r.z * std::sin(a), r.y, r.x * std::sin(a) + r.z * std::cos(a));
    out.push_back(cam);
  }
  return out;
}

/// What the views look into: the lit enclosed region (else the largest
/// enclosed one) and the room in it (with no lit region, in any enclosed
/// one); no region: from outside; no room: the region.
struct Choice {
  const Region* region = nullptr;
  std::optional<ChosenRoom> room;
};

Choice choose(const RayScene& rays, const Regions& regions, const Lighting& lights) {
  const std::vector<const Region*> enclosed = enclosed_regions(rays, regions);
  if (enclosed.empty()) return {};
  const Region* lit = lit_region(enclosed, regions, lights);
  return {lit ? lit : enclosed.front(), choose_room_in(rays, regions, lit ? std::vector<const Region*>{lit} : enclosed, lights)};
}

} // namespace

std::vector<Camera> default_views(const RayScene& rays, const Lighting& lights, float aspect, size_t count) {
  count = std::max<size_t>(count, 1);
  const Regions regions(rays);
  const Choice choice = choose(rays, regions, lights);
  if (choice.room) {
    std::vector<Camera> inside = inside_views(rays, choice.room->space, regions.voxel_size(), lights, aspect, count);
    if (!inside.empty()) return inside;
  }
  if (choice.region) {
    std::vector<Camera> inside = inside_views(rays, region_space(regions, *choice.region), regions.voxel_size(), lights, aspect, count);
    if (!inside.empty()) return inside;
  }
  return outside_views(rays.scene(), aspect, count);
}

Camera default_view(const RayScene& rays, const Lighting& lights, float aspect) {
  return default_views(rays, lights, aspect, 1).front();
}

int default_view_room(const RayScene& rays, const Lighting& lights) {
  const Regions regions(rays);
  const Choice choice = choose(rays, regions, lights);
  return choice.room ? choice.room->region : choice.region ? choice.region->id : -1;
}

} // namespace hilight
