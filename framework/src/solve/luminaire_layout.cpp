// The geometry of luminaire layouts: outlines, spacing, the room, its
// arrays, and glare (solve/luminaire_layout.hpp).
#include "hilight/solve/luminaire_layout.hpp"

#include "hilight/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace hilight {

namespace {

constexpr float kUp = 0.7f;  // |n.y| above this: a floor or a ceiling

Vec3 horizontal(Vec3 d) {
  d.y = 0.f;
  const float n = glm::length(d);
  return n > 1e-6f ? d / n : Vec3(1.f, 0.f, 0.f);
}

float median(std::vector<float> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Up to `most` of `items`, evenly spaced.
template <class T> std::vector<T> thin(const std::vector<T>& items, size_t most) {
  if (items.size() <= most) return items;
  std::vector<T> out;
  for (size_t k = 0; k < most; ++k) out.push_back(items[k * items.size() / most]);
  return out;
}

/// The lowest upward-facing surface under `p` (through desks and tables).
std::optional<float> lowest_floor(const RayScene& rays, Vec3 p) {
  std::optional<float> floor;
  for (int step = 0; step < 32; ++step) {
    const Hit hit = rays.intersect(p, Vec3(0.f, -1.f, 0.f));
    if (!hit.valid()) break;
    const Vec3 q = rays.hit_position(hit);
    if (rays.face_normals()[hit.triangle].y > kUp) floor = q.y;
    p = Vec3(p.x, q.y - rays.epsilon(), p.z);
  }
  return floor;
}

} // namespace

glm::vec2 luminous_opening(const Light& light) {
  switch (light.type) {
    case LightType::Rectangle: return {light.size[0], light.size[1]};
    case LightType::Disk: return {light.size[0], light.size[0]};
    case LightType::Line: return {light.size[0], 0.f};
    case LightType::Luminaire:
      if (light.profile) {
        const Photometry& p = *light.profile;
        if (p.opening_round) {
          const float d = float(std::max(p.opening_length, p.opening_width));
          return {d, d};
        }
        return {float(p.opening_length), float(p.opening_width)};
      }
      return {0.f, 0.f};
    default: return {0.f, 0.f};
  }
}

glm::vec2 luminaire_size(const Light& light) {
  const glm::vec2 opening = luminous_opening(light);
  if (light.type != LightType::Luminaire || !light.profile) return opening;
  const Photometry& p = *light.profile;
  const float length = float(p.body_round ? std::max(p.body_length, p.body_width) : p.body_length);
  const float width = float(p.body_round ? length : p.body_width);
  // The body holds the opening: a file's smaller body (or none) leaves the opening.
  return glm::max(opening, glm::vec2(length, width));
}

Vec3 length_axis(const Light& light) { return horizontal(is_area(light.type) ? light.up : LuminaireFrame::of(light).c0); }

Footprint footprint_of(const Light& light, glm::vec2 size) {
  Footprint f;
  f.centre = light.position;
  f.axis = length_axis(light);
  f.length = size[0];
  f.width = size[1];
  return f;
}

Light turned(const Light& light, float degrees) {
  if (degrees == 0.f) return light;
  Light out = light;
  if (is_area(light.type)) {
    const Vec3 nadir = glm::normalize(light.direction);
    const float a = float(double(degrees) * kPi / 180.0);
    out.up = glm::normalize(std::cos(a) * light.up + std::sin(a) * glm::cross(light.up, nadir));
  } else {
    out.spin_deg = light.spin_deg + degrees;
  }
  return out;
}

bool too_close(const Footprint& a, const Footprint& b, const SpacingRules& rules) {
  const Vec3 d(b.centre.x - a.centre.x, 0.f, b.centre.z - a.centre.z);
  if (rules.min_spacing > 0 && double(glm::length(d)) < rules.min_spacing - 1e-6) return true;
  if (glm::length(d) < 1e-6f) return true;  // two luminaires never share a centre
  if (a.length <= 0.f && a.width <= 0.f && b.length <= 0.f && b.width <= 0.f) return false;
  // Separating axes: the sides of both outlines (a line's body a millimetre wide).
  const Vec3 up(0.f, 1.f, 0.f);
  const Vec3 axes[4] = {a.axis, glm::cross(up, a.axis), b.axis, glm::cross(up, b.axis)};
  const auto half = [&](const Footprint& f, const Vec3& n) {
    const float width = f.length > 0.f ? std::max(f.width, 1e-3f) : f.width;
    return 0.5f * (f.length * std::abs(glm::dot(f.axis, n)) + width * std::abs(glm::dot(glm::cross(up, f.axis), n)));
  };
  for (const Vec3& n : axes) {
    const float gap = std::abs(glm::dot(d, n)) - half(a, n) - half(b, n);
    if (gap > -1e-4f) return false;  // separated (or touching) along n
  }
  return true;
}

bool clear_of_walls(const RayScene& rays, const Footprint& f) {
  if (f.length <= 0.f && f.width <= 0.f) return true;
  const Vec3 across = glm::cross(Vec3(0.f, 1.f, 0.f), f.axis);
  const Vec3 hl = 0.5f * f.length * f.axis, hw = 0.5f * f.width * across;
  for (const Vec3& r : {hl, -hl, hw, -hw, hl + hw, hl - hw, -hl + hw, -hl - hw}) {
    const float len = glm::length(r);  // touching a wall is clear: a millimetre short of the outline
    if (len > 2e-3f && rays.occluded(f.centre, r / len, len - 1e-3f)) return false;
  }
  return true;
}

RoomFrame room_frame(const LightSpace& space, const IlluminanceCriteria& criteria, float mount_y) {
  const RayScene& rays = space.rays();
  std::vector<Vec3> points;
  float half = 0.f, plane = -std::numeric_limits<float>::max();
  for (const auto& g : criteria.grids)
    if (g.kind == CriterionGrid::Kind::WorkPlane) {
      points.insert(points.end(), g.points.begin(), g.points.end());
      half = std::max(half, 0.5f * float(g.spacing));
      for (const Vec3& p : g.points) plane = std::max(plane, p.y);
    }
  if (points.empty()) {
    for (const auto& g : criteria.grids) {
      points.insert(points.end(), g.points.begin(), g.points.end());
      half = std::max(half, 0.5f * float(g.spacing));
    }
    Bounds b;
    for (const Vec3& p : points) b.extend(p);
    plane = b.lo.y;
  }
  RoomFrame room;
  // The room's axes: the smallest rectangle around the points (0.5° steps; square to the world when that is as small).
  double best = std::numeric_limits<double>::max();
  for (int k = 0; k < 180; ++k) {
    const float a = float(k) * 0.5f * float(kPi) / 180.f;
    const Vec3 u(std::cos(a), 0.f, std::sin(a)), v(-std::sin(a), 0.f, std::cos(a));
    float ulo = std::numeric_limits<float>::max(), uhi = -ulo, vlo = ulo, vhi = -ulo;
    for (const Vec3& p : points) {
      ulo = std::min(ulo, glm::dot(p, u)), uhi = std::max(uhi, glm::dot(p, u));
      vlo = std::min(vlo, glm::dot(p, v)), vhi = std::max(vhi, glm::dot(p, v));
    }
    const double area = double(uhi - ulo + 2 * half) * double(vhi - vlo + 2 * half);
    if (area < best * (1 - 1e-3)) {
      best = area;
      room.u = u, room.v = v;
      room.u_lo = ulo - half, room.u_hi = uhi + half, room.v_lo = vlo - half, room.v_hi = vhi + half;
    }
  }
  room.plane_y = plane;
  room.mount_y = mount_y;
  // Pushed out to the walls: horizontal rays at the mount height from the points along each side.
  const float probe_y = std::max(plane + 0.05f, mount_y);
  const auto push = [&](const Vec3& axis, float& side, float sign) {
    const Vec3 out = sign * axis;
    std::vector<Vec3> near;
    for (const Vec3& p : points)
      if (std::abs(glm::dot(p, axis) - (side - sign * half)) <= half + 1e-4f) near.push_back(p);
    std::vector<float> walls;
    for (const Vec3& p : thin(near, 9)) {
      const Vec3 from(p.x, probe_y, p.z);
      if (rays.inside_solid(from)) continue;
      const Hit hit = rays.intersect(from, out, 50.f);
      if (hit.valid()) walls.push_back(sign * glm::dot(rays.hit_position(hit), axis));
    }
    // The wall (the half cell around the points may reach past it: a cell is at most the grid's spacing).
    side = sign * (walls.empty() ? sign * side + 0.5f : median(walls));
  };
  push(room.u, room.u_lo, -1.f);
  push(room.u, room.u_hi, 1.f);
  push(room.v, room.v_lo, -1.f);
  push(room.v, room.v_hi, 1.f);
  // The floor: the lowest upward surface under the work plane.
  std::vector<float> floors;
  for (const Vec3& p : thin(points, 40))
    if (const auto f = lowest_floor(rays, p + Vec3(0.f, 1e-3f, 0.f))) floors.push_back(*f);
  room.floor_y = floors.empty() ? plane - 0.75f : median(floors);
  // Floor area: the rectangle's cells that stand in the rooms of the points, free at mid height or
  // just under the mount (over a cabinet; under a sloping ceiling the first).
  const float mid = 0.5f * (plane + std::max(mount_y, plane + 0.1f)), high = std::max(mid, mount_y - 0.05f);
  std::set<int> ids;
  for (const Vec3& p : thin(points, 200))
    if (const int r = space.regions().at(Vec3(p.x, mid, p.z)); r >= 0) ids.insert(r);
  const double rect = double(room.length()) * double(room.width());
  const float step = float(std::max(0.05, std::sqrt(rect / 40000.0)));
  size_t inside = 0;
  for (float a = room.u_lo + 0.5f * step; a < room.u_hi; a += step)
    for (float b = room.v_lo + 0.5f * step; b < room.v_hi; b += step) {
      for (float y : {mid, high}) {
        const Vec3 p = room.at(a, b, y);
        if ((ids.empty() || ids.count(space.regions().at(p))) && !rays.inside_solid(p)) {
          ++inside;
          break;
        }
      }
    }
  room.floor_area = double(inside) * double(step) * double(step);
  return room;
}

std::string ArrayLayout::describe() const {
  char text[128];
  std::snprintf(text, sizeof(text), "%d × %d at %.2f × %.2f m", columns, rows, double(du), double(dv));
  std::string out = text;
  if (positions.size() < size_t(columns) * size_t(rows)) out += ", " + std::to_string(positions.size()) + " in the room";
  return out;
}

std::vector<ArrayLayout> room_arrays(const LightSpace& space, const RoomFrame& room, const Light& luminaire, const ArrayRules& rules,
                                     const std::vector<float>& turns, size_t count, ArrayFitCache* cache) {
  std::vector<ArrayLayout> out;
  if (count == 0) return out;
  const float tile = float(rules.tile);
  float ou = room.u_lo, ov = room.v_lo;
  if (rules.grid_origin) {
    const Vec3 o(float(rules.grid_origin->x), 0.f, float(rules.grid_origin->y));
    ou = glm::dot(o, room.u), ov = glm::dot(o, room.v);
  }
  // Centres along one side: n in the middle of equal cells, or on tiles (k tiles apart), centred.
  const auto along = [&](int n, float lo, float hi, float extent, float origin, std::vector<std::pair<float, std::vector<float>>>& options) {
    const float span = hi - lo, centre = 0.5f * (lo + hi);
    if (tile <= 0.f) {
      const float d = span / float(n);
      std::vector<float> c;
      for (int i = 0; i < n; ++i) c.push_back(lo + (float(i) + 0.5f) * d);
      options.push_back({d, c});
      return;
    }
    std::set<int> ks;
    if (n == 1) ks.insert(0);
    else {
      const float ideal = span / (float(n) * tile);
      ks.insert(std::max(1, int(std::floor(ideal))));
      ks.insert(std::max(1, int(std::ceil(ideal))));
    }
    for (int k : ks) {
      const float first = (centre - origin) / tile - 0.5f - 0.5f * float((n - 1) * k);
      for (int a : {int(std::lround(first)), int(std::lround(first)) - 1, int(std::lround(first)) + 1}) {
        std::vector<float> c;
        for (int i = 0; i < n; ++i) c.push_back(origin + (float(a + i * k) + 0.5f) * tile);
        if (c.front() - 0.5f * extent >= lo - 1e-4f && c.back() + 0.5f * extent <= hi + 1e-4f) {
          options.push_back({n == 1 ? span : float(k) * tile, c});
          break;
        }
      }
    }
  };
  const float h = std::max(1e-3f, rules.height_over_plane);
  // An L-shaped (or any not rectangular) room: grids over its rectangle, clipped.
  const double rectangle = double(room.length()) * double(room.width());
  const double fill = rectangle > 0 ? room.floor_area / rectangle : 1.0;
  const bool clip = fill > 0 && fill < kClippedFill;
  const size_t most_cells = clip ? size_t(std::ceil(1.25 * double(count) / fill)) : count;
  for (size_t t = 0; t < turns.size(); ++t) {
    const float turn = turns[t];
    const Light l = turned(luminaire, turn);
    const bool lengthwise = std::abs(glm::dot(length_axis(l), room.u)) > 0.7f;
    const float eu = lengthwise ? rules.size[0] : rules.size[1], ev = lengthwise ? rules.size[1] : rules.size[0];
    // Where the grid's places fit: all of them (an array of `count`), or
    // with `clip` those that do (kept only if `count` of them do).
    const auto fitting = [&](const std::vector<float>& ucs, const std::vector<float>& vcs) {
      std::vector<Vec3> kept;
      for (float v : vcs)
        for (float u : ucs) {
          const auto at = space.place(room.at(u, v, room.mount_y));
          bool fits = at && space.admissible(*at);
          if (fits) {
            Light placed = l;
            placed.position = *at;
            fits = clear_of_walls(space.rays(), footprint_of(placed, rules.size));
          }
          if (fits) kept.push_back(*at);
          else if (!clip) return std::vector<Vec3>();
        }
      return kept;
    };
    for (size_t cells = count; cells <= most_cells; ++cells)
      for (size_t nu = 1; nu <= cells; ++nu) {
        if (cells % nu) continue;
        const size_t nv = cells / nu;
        if (nu > 4096 || nv > 4096) continue;
        std::vector<std::pair<float, std::vector<float>>> us, vs;
        along(int(nu), room.u_lo, room.u_hi, eu, ou, us);
        along(int(nv), room.v_lo, room.v_hi, ev, ov, vs);
        for (size_t iu = 0; iu < us.size(); ++iu)
          for (size_t iv = 0; iv < vs.size(); ++iv) {
            const auto& [du, ucs] = us[iu];
            const auto& [dv, vcs] = vs[iv];
            if (du + 1e-4f < eu || dv + 1e-4f < ev) continue;  // the outlines would overlap
            if (rules.spacing.min_spacing > 0 && ((nu > 1 && double(du) < rules.spacing.min_spacing - 1e-6) ||
                                                  (nv > 1 && double(dv) < rules.spacing.min_spacing - 1e-6)))
              continue;
            if (rules.spacing.max_spacing_ratio > 0 &&
                ((nu > 1 && double(du) > rules.spacing.max_spacing_ratio * double(h) + 1e-6) ||
                 (nv > 1 && double(dv) > rules.spacing.max_spacing_ratio * double(h) + 1e-6)))
              continue;
            if (!rules.exact_count && std::max(du, dv) > 2.f * std::min(du, dv) + 1e-4f) continue;  // spacings within 2:1
            std::vector<Vec3> kept;
            const std::string key = std::to_string(t) + "/" + std::to_string(nu) + "x" + std::to_string(nv) + "/" +
                                    std::to_string(iu) + "," + std::to_string(iv);
            if (cache && cache->fits.count(key)) kept = cache->fits.at(key);
            else {
              kept = fitting(ucs, vcs);
              if (cache) cache->fits[key] = kept;
            }
            if (kept.size() != count) continue;
            ArrayLayout a;
            a.columns = int(nu), a.rows = int(nv), a.du = du, a.dv = dv, a.turn = turn;
            a.positions = std::move(kept);
            out.push_back(std::move(a));
          }
      }
  }
  return out;
}

double guth_position_index(double tau, double sigma) {
  tau = std::clamp(tau, 0.0, 90.0);
  sigma = std::clamp(sigma, 0.0, 90.0);
  const double a = (35.2 - 0.31889 * tau - 1.22 * std::exp(-2.0 * tau / 9.0)) * 1e-3 * sigma;
  const double b = (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma;
  return std::exp(a + b);
}

std::vector<GlareObserver> standard_observers(const RoomFrame& room, float eye_height) {
  const float y = room.floor_y + eye_height;
  const float cu = 0.5f * (room.u_lo + room.u_hi), cv = 0.5f * (room.v_lo + room.v_hi);
  const float inset = std::min(0.1f, 0.25f * std::min(room.length(), room.width()));
  std::vector<GlareObserver> out;
  out.push_back({"−u side, looking along +u", room.at(room.u_lo + inset, cv, y), room.u});
  out.push_back({"+u side, looking along −u", room.at(room.u_hi - inset, cv, y), -room.u});
  out.push_back({"−v side, looking along +v", room.at(cu, room.v_lo + inset, y), room.v});
  out.push_back({"+v side, looking along −v", room.at(cu, room.v_hi - inset, y), -room.v});
  return out;
}

GlareTerms glare_terms(const RayScene& rays, const Light& light, double area, const GlareObserver& observer) {
  GlareTerms t;
  if (!light.profile) return t;
  const Vec3 to_eye = observer.eye - light.position;
  const float r = glm::length(to_eye);
  if (!(r > 1e-4f)) return t;
  const Vec3 dir = to_eye / r;  // luminaire → eye
  const Vec3 back = -dir;       // eye → luminaire
  if (rays.occluded(observer.eye, back, std::max(0.f, r - 8.f * rays.epsilon()))) return t;
  const LuminaireFrame frame = LuminaireFrame::of(light);
  const double candela = kLumensPerWatt * luminance(light.intensity) * double(luminaire_factor(light, frame, dir));
  if (!(candela > 0)) return t;
  const Vec3 view = horizontal(observer.view);
  t.direct_lux = candela * std::max(0.0, double(glm::dot(view, back))) / (double(r) * double(r));
  const double cf = glm::dot(back, view), cu = back.y;
  const double cos_gamma = glm::dot(glm::normalize(light.direction), dir);
  if (cf <= 0 || cu <= 0 || cos_gamma <= 0 || !(area > 0)) return t;  // behind, below the line of sight, or its back
  const Vec3 right = glm::cross(view, Vec3(0.f, 1.f, 0.f));
  const double sigma = std::acos(std::clamp(cf, -1.0, 1.0)) * 180.0 / kPi;
  const double tau = std::atan2(std::abs(double(glm::dot(back, right))), cu) * 180.0 / kPi;
  const double p = guth_position_index(tau, sigma);
  const double projected = area * std::max(cos_gamma, 0.05);
  // L²ω/p² with L = I/A_p and ω = A_p/r².
  t.glare = candela * candela / (projected * double(r) * double(r) * p * p);
  return t;
}

double unified_glare_rating(double sum_glare, double indirect_lux) {
  if (!(sum_glare > 0)) return std::numeric_limits<double>::quiet_NaN();
  const double background = std::max(indirect_lux, 1e-6) / kPi;
  return 8.0 * std::log10(0.25 * sum_glare / background);
}

} // namespace hilight
