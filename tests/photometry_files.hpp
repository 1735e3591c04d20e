#pragma once
// IES LM-63 and EULUMDAT files written by the tests (Debian ships none):
// a known distribution in, so what hilight reads can be checked against it.
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace test {

/// from, from + step, ..., to.
inline std::vector<double> angles(double from, double to, double step) {
  std::vector<double> v;
  for (double a = from; a <= to + 1e-9; a += step) v.push_back(a);
  return v;
}

inline std::string joined(const std::vector<double>& v) {
  std::ostringstream s;
  for (size_t i = 0; i < v.size(); ++i) s << (i ? (i % 10 ? " " : "\n") : "") << v[i];
  return s.str();
}

/// An IES LM-63-2002 file of type C (1) or B (2) with candela f(h, v) on the
/// given vertical and horizontal angles; one lamp of `lumens`, `watts` input.
inline std::string ies_text(const std::vector<double>& vertical, const std::vector<double>& horizontal,
                            const std::function<double(double, double)>& f, int type = 1, const std::string& tilt = "TILT=NONE",
                            double multiplier = 1, double ballast = 1, double lumens = 1000, double watts = 36) {
  std::ostringstream s;
  s << "IESNA:LM-63-2002\n[TEST] generated\n[MANUFAC] hilight tests\n" << tilt << "\n";
  s << "1 " << lumens << " " << multiplier << " " << vertical.size() << " " << horizontal.size() << " " << type << " 2 0.1 0.2 0.05\n";
  s << ballast << " 1 " << watts << "\n" << joined(vertical) << "\n" << joined(horizontal) << "\n";
  for (double h : horizontal) {
    std::vector<double> row;
    for (double v : vertical) row.push_back(f(h, v));
    s << joined(row) << "\n";
  }
  return s.str();
}

/// A EULUMDAT file: intensities in cd/klm per stored plane, one lamp set of
/// `lumens` and `watts`.
inline std::string ldt_text(int isym, const std::vector<double>& c_angles, const std::vector<double>& gammas,
                            const std::vector<std::vector<double>>& planes, double lumens, double watts = 25) {
  std::ostringstream s;
  s << "hilight tests\n1\n" << isym << "\n" << c_angles.size() << "\n" << (c_angles.size() > 1 ? c_angles[1] - c_angles[0] : 0) << "\n"
    << gammas.size() << "\n" << gammas[1] - gammas[0] << "\nreport\nluminaire\nnumber\nfile.ldt\n2026-11-24\n";
  for (int k = 0; k < 9; ++k) s << "100\n";
  s << "100\n80\n1\n0\n1\n1\nLED\n" << lumens << "\n3000\n80\n" << watts << "\n";
  for (int k = 0; k < 10; ++k) s << "0.5\n";
  for (double c : c_angles) s << c << "\n";
  for (double g : gammas) s << g << "\n";
  for (const auto& plane : planes)
    for (double v : plane) s << v << "\n";
  return s.str();
}

/// A linear luminaire, quadrant-symmetric: wide in its C0–C180 plane
/// (cos^0.5 γ), narrow across it (cos^12 γ); 2000 lm, 20 W. What the aim
/// tests turn.
inline std::string linear_ies() {
  return ies_text(angles(0, 90, 5), angles(0, 90, 15), [](double c, double g) {
    const double cc = std::cos(c * 3.14159265358979323846 / 180.0), gg = std::cos(g * 3.14159265358979323846 / 180.0);
    return 1000.0 * (cc * cc * std::pow(gg, 0.5) + (1 - cc * cc) * std::pow(gg, 12.0));
  }, 1, "TILT=NONE", 1, 1, 2000, 20);
}

} // namespace test
