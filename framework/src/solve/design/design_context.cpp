// The design's set-up and the renders every step shares (design_steps.hpp).
#include "design_steps.hpp"

namespace hilight::design {

DesignContext::DesignContext(Renderer& reference_, const LightSpace& space_, const Light& luminaire_, const IlluminanceCriteria& criteria_,
                             const DesignSettings& settings_, DesignReport& report_)
    : reference(reference_), space(space_), luminaire(luminaire_), criteria(criteria_), settings(settings_), report(report_),
      rays(space_.rays()), profile(*luminaire_.profile), started(Clock::now()) {
  peak = profile.peak(), rated = profile.flux(), mf = settings.maintenance_factor, margin = settings.margin;
  report.maintenance_factor = mf;
  report.margin = margin;

  // The area, the lattice step, the mount and the room.
  double finest = std::numeric_limits<double>::max();
  plane = -std::numeric_limits<float>::max();
  for (const auto& g : criteria.grids) {
    for (const Vec3& p : g.points) area.extend(p);
    if (g.spacing > 0) finest = std::min(finest, g.spacing);
    if (g.kind == CriterionGrid::Kind::WorkPlane)
      for (const Vec3& p : g.points) plane = std::max(plane, p.y);
  }
  if (area.empty()) throw InputError("the criteria have no point");
  if (plane == -std::numeric_limits<float>::max()) plane = area.center().y;
  // A third of the finest grid's spacing, but no finer than 15 cm (the zones' narrow bands have fine grids).
  step = settings.candidate_spacing > 0                  ? float(settings.candidate_spacing)
         : finest < std::numeric_limits<double>::max() ? std::max(float(finest / 3.0), 0.15f)
                                                       : area.diagonal() / 20.f;
  if (!(step > 0.f)) throw InputError("the criteria's points are all in one place: no room to spread luminaires");
  layers = candidate_layers(space, plane, step);
  std::vector<float> mounts;
  for (const auto& g : criteria.grids)
    for (size_t i = 0; i < g.points.size(); i += std::max<size_t>(1, g.points.size() / 25))
      if (const auto at = space.place(Vec3(g.points[i].x, layers.back(), g.points[i].z)); at && space.admissible(*at)) mounts.push_back(at->y);
  std::sort(mounts.begin(), mounts.end());
  mount_y = mounts.empty() ? layers.back() : mounts[mounts.size() / 2];
  room = room_frame(space, criteria, mount_y);
  report.room = room;
  size = luminaire_size(luminaire);
  report.luminaire_size = size;
  const glm::vec2 opening = luminous_opening(luminaire);
  luminous_area = luminaire.type == LightType::Disk || (luminaire.type == LightType::Luminaire && profile.opening_round)
                      ? kPi / 4 * double(opening[0]) * double(opening[0])
                      : double(opening[0]) * double(opening[1]);
  report.luminous_area = luminous_area;

  // What cannot fit the room.
  const float L = room.length(), W = room.width();
  room_size = metres(L) + " × " + metres(W) + " m";
  if (std::max(size[0], size[1]) > std::max(L, W) + 1e-4f || std::min(size[0], size[1]) > std::min(L, W) + 1e-4f)
    throw InputError("a luminaire of " + metres(size[0]) + " × " + metres(size[1]) + " m does not fit the room the criteria lie in (" +
                     room_size + ")");
  if (settings.spacing.min_spacing > double(std::hypot(L, W)))
    throw InputError("--min-spacing " + metres(settings.spacing.min_spacing) + ": no two luminaires fit that far apart in the room (" +
                     room_size + ")");
  if (settings.ceiling_grid > 0 && settings.ceiling_grid > double(std::min(L, W)) + 1e-4)
    throw InputError("--ceiling-grid " + metres(settings.ceiling_grid) + ": a tile larger than the room (" + room_size + ")");
  if (settings.ugr_max > 0 && !(luminous_area > 0))
    throw InputError("--ugr-max needs the luminaire's luminance, so its luminous area: " + profile.source +
                     " gives no opening (give --luminaire-size W,L)");
  if (settings.fixed_count && settings.max_count && settings.fixed_count > settings.max_count)
    throw InputError("--lights " + std::to_string(settings.fixed_count) + " is more than --place count allows (" +
                     std::to_string(settings.max_count) + ")");

  // Observers, points.
  if (luminous_area > 0) observers = standard_observers(room, settings.eye_height());
  pts.all = criteria.points();
  pts.criteria = pts.all.positions.size();
  for (const auto& g : criteria.grids) {
    const size_t from = pts.all.positions.size();
    if (margin > 0) add_between(rays, g, pts.all);
    pts.between.push_back({from, pts.all.positions.size() - from});
  }
  pts.eyes_first = pts.all.positions.size();
  for (const auto& o : observers) {
    pts.all.positions.push_back(o.eye);
    pts.all.normals.push_back(glm::normalize(o.view));
  }
  pts.cylinders_first = pts.all.positions.size();
  if (settings.cylindrical_min > 0) {
    const std::vector<Vec3> cylinders = cylinder_places(rays, criteria, room.floor_y, settings.eye_height());
    if (cylinders.empty()) throw InputError("--cylindrical-min: no work plane point has room for a person's head over it");
    for (const Vec3& at : cylinders)
      for (const Vec3& n : kCylinderNormals) {
        pts.all.positions.push_back(at);
        pts.all.normals.push_back(n);
      }
    pts.cylinders = cylinders.size();
  }
  pts.all.albedo.assign(pts.all.positions.size(), Rgb(1.f));
  lux_points = pts.eyes_first;
}

Light DesignContext::light_at(const Place& c, double dimming) const {
  Light l = turned(luminaire, c.turn);
  l.position = c.position;
  if (c.aim != Vec3(0.f)) {  // tilted: the aim, and an area source's length axis kept square to it
    l.direction = c.aim;
    if (is_area(l.type)) l.up = glm::normalize(l.up - glm::dot(l.up, c.aim) * c.aim);
  }
  l.intensity = Rgb(float(dimming * peak / kLumensPerWatt));
  return l;
}

std::vector<Field> DesignContext::render(const std::vector<Place>& places) const {
  Lighting unit;
  for (const auto& c : places) unit.push_back(light_at(c, kLumensPerWatt / peak));
  const std::vector<Rgb> phi = reference.unit_responses(pts.all, unit);
  std::vector<Field> out(places.size());
  const size_t n = pts.all.positions.size();
  for (size_t j = 0; j < places.size(); ++j) {
    std::vector<double> e = lux_from_radiance(std::span<const Rgb>(phi.data() + j * n, n));
    for (double& v : e) v *= peak / kLumensPerWatt;  // φ is for 1 W/sr at the peak; full output is peak/683
    out[j].lux.assign(e.begin(), e.begin() + long(lux_points));
    for (double& v : out[j].lux) v *= mf;
    if (pts.cylinders) {
      double sum = 0;
      for (size_t k = 0; k < 4 * pts.cylinders; ++k) sum += e[pts.cylinders_first + k];
      out[j].cylindrical = mf * sum / double(4 * pts.cylinders);
    }
    const Light full = light_at(places[j], 1.0);
    for (size_t o = 0; o < observers.size(); ++o) {
      const GlareTerms t = glare_terms(rays, full, luminous_area, observers[o]);
      out[j].glare.push_back(t.glare);
      out[j].indirect.push_back(std::max(0.0, e[pts.eyes_first + o] - t.direct_lux));
    }
  }
  return out;
}

bool DesignContext::lights_some(const Field& f) const {
  return *std::max_element(f.lux.begin(), f.lux.begin() + long(pts.criteria)) > 0;
}

} // namespace hilight::design
