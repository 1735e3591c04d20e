// EULUMDAT reader (io/photometry_io.hpp): one value per line, in the order
// the format fixes; intensities in cd per 1000 lm of lamp flux.
#include "hilight/error.hpp"
#include "hilight/io/text_file.hpp"
#include "hilight/io/photometry_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace hilight {

namespace {

class Lines {
public:
  Lines(const std::string& text, std::string source) : m_source(std::move(source)) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      m_lines.push_back(line);
    }
  }
  std::string text(const std::string& what) {
    if (m_at >= m_lines.size()) throw InputError(m_source, "ends before " + what + " (line " + std::to_string(m_at + 1) + ", truncated?)");
    return m_lines[m_at++];
  }
  double number(const std::string& what) {
    std::string t = text(what);
    std::replace(t.begin(), t.end(), ',', '.');  // some writers use a decimal comma
    const size_t first = t.find_first_not_of(" \t");
    char* end = nullptr;
    const double v = first == std::string::npos ? NAN : std::strtod(t.c_str() + first, &end);
    if (first == std::string::npos || end == t.c_str() + first || !std::isfinite(v) ||
        t.find_first_not_of(" \t", size_t(end - t.c_str())) != std::string::npos)
      throw InputError(m_source, "line " + std::to_string(m_at) + " (" + what + "): '" + t + "' is not a number");
    return v;
  }
  size_t whole(const std::string& what, size_t least, size_t most) {
    const double v = number(what);
    if (v < double(least) || v > double(most) || v != std::floor(v))
      throw InputError(m_source, "line " + std::to_string(m_at) + ": " + what + " must be a whole number from " + std::to_string(least) +
                                     " to " + std::to_string(most));
    return size_t(v);
  }

private:
  std::string m_source;
  std::vector<std::string> m_lines;
  size_t m_at = 0;
};

} // namespace

Photometry parse_ldt(const std::string& text, const std::string& source) {
  Lines in(text, source);
  Photometry p;
  p.source = source;
  const std::string company = in.text("the company");
  in.whole("the type indicator Ityp", 0, 3);
  const size_t isym = in.whole("the symmetry Isym", 0, 4);
  const size_t mc = in.whole("the number of C planes Mc", 1, 3600);
  in.number("the distance between C planes Dc");
  const size_t ng = in.whole("the number of gamma angles Ng", 1, 3600);
  in.number("the distance between gamma angles Dg");
  in.text("the measurement report");
  const std::string name = in.text("the luminaire name"), number = in.text("the luminaire number");
  for (const char* what : {"the file name", "the date/user"}) in.text(what);
  p.product = product_text({company, name, number});
  // Luminaire length, width, height; then the luminous area's length (or
  // diameter) and width (0: round), mm; then its heights.
  double dimension[9];
  for (double& d : dimension) d = in.number("a luminaire or luminous area dimension");
  p.opening_round = dimension[4] == 0 && dimension[3] > 0;
  p.opening_length = std::abs(dimension[3]) * 1e-3;
  p.opening_width = p.opening_round ? p.opening_length : std::abs(dimension[4]) * 1e-3;
  p.body_round = dimension[1] == 0 && dimension[0] > 0;
  p.body_length = std::abs(dimension[0]) * 1e-3;
  p.body_width = p.body_round ? p.body_length : std::abs(dimension[1]) * 1e-3;
  in.number("the downward flux fraction");
  in.number("the light output ratio");
  const double conversion = in.number("the conversion factor for luminous intensities");
  in.number("the tilt during measurement");
  const size_t sets = in.whole("the number of standard sets of lamps", 1, 100);
  std::vector<double> lamps(sets), flux(sets), watts(sets);
  for (auto& n : lamps) n = in.number("the number of lamps");
  for (size_t s = 0; s < sets; ++s) in.text("the type of lamps");
  for (auto& f : flux) f = in.number("the total luminous flux of lamps");
  for (size_t s = 0; s < sets; ++s) in.text("the colour temperature");
  for (size_t s = 0; s < sets; ++s) in.text("the colour rendering index");
  for (auto& w : watts) w = in.number("the wattage including ballast");
  for (int k = 0; k < 10; ++k) in.number("a direct ratio");
  std::vector<double> c_angles(mc);
  for (auto& c : c_angles) c = in.number("a C angle");
  p.vertical.resize(ng);
  for (auto& g : p.vertical) g = in.number("a gamma angle");
  for (size_t i = 1; i < mc; ++i)
    if (!(c_angles[i] > c_angles[i - 1])) throw InputError(source, "C angles must increase");
  for (size_t i = 1; i < ng; ++i)
    if (!(p.vertical[i] > p.vertical[i - 1])) throw InputError(source, "gamma angles must increase");
  if (p.vertical.front() < 0 || p.vertical.back() > 180) throw InputError(source, "gamma angles must lie in 0-180");
  if (c_angles.front() < 0 || c_angles.back() > 360) throw InputError(source, "C angles must lie in 0-360");
  // The planes stored: all (Isym 0), one (1), C0-C180 (2), C90-C270 (3), C0-C90 (4).
  std::vector<double> stored;
  for (double c : c_angles)
    if (isym == 0 || (isym == 2 && c <= 180) || (isym == 3 && c >= 90 && c <= 270) || (isym == 4 && c <= 90)) stored.push_back(c);
  if (isym == 1) stored = {0.0};
  if (stored.empty()) throw InputError(source, "no C plane is stored for Isym " + std::to_string(isym));
  // A symmetry's stored planes run its whole range (as an IES file's must):
  // between a gap's edges there is nothing to mirror or interpolate.
  const double from = isym == 3 ? 90.0 : 0.0, to = isym == 2 ? 180.0 : isym == 3 ? 270.0 : 90.0;
  if (isym >= 2 && (stored.front() != from || stored.back() != to)) {
    char message[160];
    std::snprintf(message, sizeof(message), "Isym %d stores the C planes from %g to %g, but this file's run from %g to %g", int(isym), from, to,
                  stored.front(), stored.back());
    throw InputError(source, message);
  }
  p.horizontal = stored;
  p.symmetry = isym == 1 ? Photometry::Symmetry::Rotational
               : isym == 2 ? Photometry::Symmetry::AboutC0C180
               : isym == 3 ? Photometry::Symmetry::AboutC90C270
               : isym == 4 ? Photometry::Symmetry::Quadrants
                           : Photometry::Symmetry::None;
  double total_flux = 0;
  for (size_t s = 0; s < sets; ++s) {
    if (flux[s] < 0 || lamps[s] < 0 || watts[s] < 0) throw InputError(source, "a lamp count, flux or wattage is negative");
    total_flux += flux[s];
    p.input_watts += watts[s];
  }
  if (!(total_flux > 0)) throw InputError(source, "the lamps' total luminous flux must be positive (intensities are per 1000 lm)");
  if (!(conversion > 0)) throw InputError(source, "the conversion factor must be positive");
  p.rated_lumens = total_flux;
  const double scale = conversion * total_flux / 1000.0;
  p.candela.resize(stored.size() * ng);
  for (size_t k = 0; k < p.candela.size(); ++k) {
    const double v = in.number("luminous intensity " + std::to_string(k + 1) + " of " + std::to_string(p.candela.size()));
    if (v < 0) throw InputError(source, "luminous intensity " + std::to_string(k + 1) + " is negative");
    p.candela[k] = v * scale;
    if (!(p.candela[k] <= kBrightestCandela)) {
      char message[160];
      std::snprintf(message, sizeof(message), "luminous intensity %zu comes to %.3g cd, beyond any luminaire (at most 1e10 cd)", k + 1, p.candela[k]);
      throw InputError(source, message);
    }
  }
  // Isym 0 planes cover a turn: close the circle for interpolation with the
  // first plane a turn later (C = 360 when the first is at 0; a file whose
  // planes start past 0 is read at C = 0 between its last and first).
  if (isym == 0 && p.horizontal.back() < p.horizontal.front() + 360.0) {
    p.horizontal.push_back(p.horizontal.front() + 360.0);
    p.candela.insert(p.candela.end(), p.candela.begin(), p.candela.begin() + std::ptrdiff_t(ng));
  }
  return p;
}

Photometry read_photometry(const std::filesystem::path& path) {
  const std::string text = read_text_file(path, "photometry");
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".ies") return parse_ies(text, path.string());
  if (ext == ".ldt") return parse_ldt(text, path.string());
  throw InputError(path.string(), "a luminaire file must be .ies (IES LM-63) or .ldt (EULUMDAT)");
}

} // namespace hilight
