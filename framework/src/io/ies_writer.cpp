// A photometry written as IES LM-63-2002 (io/photometry_io.hpp): what tools
// that read only IES (Blender Cycles' IES node among them) need of a
// EULUMDAT luminaire.
#include "hilight/io/photometry_io.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hilight {

namespace {

/// The stored planes extended by the profile's symmetry over [0, 360]: the
/// file then needs no symmetry rule of its own, and every stored value
/// lands on a node (the candela between nodes interpolate as hilight's).
std::vector<double> full_circle(const Photometry& p) {
  std::vector<double> c{0.0, 360.0};
  for (double h : p.horizontal)
    for (double m : {h, 360.0 - h, 180.0 - h, 180.0 + h}) {
      m = std::fmod(m, 360.0);
      c.push_back(m < 0 ? m + 360.0 : m);
    }
  std::sort(c.begin(), c.end());
  c.erase(std::unique(c.begin(), c.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), c.end());
  return c;
}

std::vector<double> steps(double from, double to, double step) {
  std::vector<double> v;
  for (int k = 0; from + k * step <= to + 1e-9; ++k) v.push_back(from + k * step);
  return v;
}

/// Numbers ten to a line (LM-63 lines stay under 256 characters).
void write_numbers(std::ostream& out, const std::vector<double>& values) {
  for (size_t k = 0; k < values.size(); ++k) out << (k == 0 ? "" : k % 10 ? " " : "\n") << values[k];
  out << "\n";
}

/// A keyword line's text: printable ASCII, at most 70 characters.
std::string keyword_text(const std::string& s) {
  std::string out;
  for (char ch : s)
    if (ch >= 32 && ch < 127 && out.size() < 70) out += ch;
  return out;
}

} // namespace

std::string ies_text(const Photometry& p) {
  // Type C as stored; a type B file sampled on a grid in type C angles.
  const bool stored_c = p.type == Photometry::Type::C;
  const std::vector<double> vertical = stored_c ? p.vertical : steps(0.0, 180.0, 1.0);
  const std::vector<double> horizontal = p.symmetry == Photometry::Symmetry::Rotational && stored_c ? std::vector<double>{0.0}
                                         : stored_c                                               ? full_circle(p)
                                                                                                  : steps(0.0, 360.0, 2.5);
  std::ostringstream out;
  out.precision(9);
  out << "IESNA:LM-63-2002\n[TEST] written by hilight\n";
  if (!p.product.empty()) out << "[LUMINAIRE] " << keyword_text(p.product) << "\n";
  if (!p.source.empty()) out << "[OTHER] from " << keyword_text(p.source) << "\n";
  out << "TILT=NONE\n";
  // One lamp of the rated flux (−1: absolute photometry), multiplier 1,
  // type C, metres; a round opening as LM-63 gives it (negative sizes).
  const double lumens = p.rated_lumens > 0 ? p.rated_lumens : -1.0;
  const double width = p.opening_round ? -p.opening_length : p.opening_width, length = p.opening_round ? -p.opening_length : p.opening_length;
  out << "1 " << lumens << " 1 " << vertical.size() << " " << horizontal.size() << " 1 2 " << width << " " << length << " 0\n";
  out << "1 1 " << p.input_watts << "\n";
  write_numbers(out, vertical);
  write_numbers(out, horizontal);
  for (double c : horizontal) {
    std::vector<double> row;
    row.reserve(vertical.size());
    for (double g : vertical) row.push_back(p.intensity(c, g));
    write_numbers(out, row);
  }
  return out.str();
}

} // namespace hilight
