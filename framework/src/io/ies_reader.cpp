// IES LM-63 reader (io/photometry_io.hpp): keywords up to the TILT line, then
// numbers separated by blanks, commas or line breaks.
#include "hilight/error.hpp"
#include "hilight/io/photometry_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace hilight {

namespace {

/// The numbers after the TILT line, read one by one with what they are.
class Numbers {
public:
  Numbers(std::string text, std::string source) : m_source(std::move(source)) {
    std::replace(text.begin(), text.end(), ',', ' ');
    m_in.str(text);
  }
  double next(const std::string& what) {
    std::string token;
    if (!(m_in >> token)) throw InputError(m_source, "ends before " + what + " (truncated?)");
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || !std::isfinite(value))
      throw InputError(m_source, what + ": '" + token + "' is not a finite number");
    ++m_read;
    return value;
  }
  size_t count(const std::string& what, size_t most) {
    const double v = next(what);
    if (v < 1 || v > double(most) || v != std::floor(v))
      throw InputError(m_source, what + " must be a whole number from 1 to " + std::to_string(most) + ", not " + std::to_string(v));
    return size_t(v);
  }
  bool more() {
    std::string token;
    return bool(m_in >> token);
  }

private:
  std::string m_source;
  std::istringstream m_in;
  size_t m_read = 0;
};

void check_ascending(const std::vector<double>& a, const std::string& source, const std::string& what) {
  for (size_t i = 1; i < a.size(); ++i)
    if (!(a[i] > a[i - 1])) throw InputError(source, what + " must increase (" + std::to_string(a[i - 1]) + " then " + std::to_string(a[i]) + ")");
}

} // namespace

std::string product_text(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& part : parts) {
    std::string clean;
    for (unsigned char c : part)
      if (c >= 0x20 && c != 0x7f) clean += char(c);  // UTF-8 kept; control characters dropped
    const size_t first = clean.find_first_not_of(' '), last = clean.find_last_not_of(' ');
    if (first == std::string::npos) continue;
    if (!out.empty()) out += ' ';
    out += clean.substr(first, last - first + 1);
  }
  if (out.size() > 200) {
    out.resize(200);
    while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0x80) out.pop_back();  // no half character
    if (!out.empty() && static_cast<unsigned char>(out.back()) >= 0xC0) out.pop_back();
  }
  return out;
}

Photometry parse_ies(const std::string& text, const std::string& source) {
  Photometry p;
  p.source = source;
  // Keywords and the version line end at "TILT=".
  size_t tilt = std::string::npos;
  std::string manufacturer, name, catalogue;
  for (size_t at = 0; at < text.size();) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(at, end - at);
    const size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 5, "TILT=") == 0) {
      tilt = at + first;
      break;
    }
    if (first != std::string::npos) {
      const auto keyword = [&](const char* key, std::string& into) {
        const size_t n = std::char_traits<char>::length(key);
        if (line.compare(first, n, key) == 0 && into.empty()) into = line.substr(first + n);
      };
      keyword("[MANUFAC]", manufacturer);
      keyword("[LUMINAIRE]", name);
      keyword("[LUMCAT]", catalogue);
    }
    at = end + 1;
  }
  p.product = product_text({manufacturer, name, catalogue});
  if (tilt == std::string::npos) throw InputError(source, "no TILT= line: not an IES LM-63 file");
  const size_t tilt_end = std::min(text.find('\n', tilt), text.size());
  std::string tilt_value = text.substr(tilt + 5, tilt_end - tilt - 5);
  tilt_value.erase(std::remove_if(tilt_value.begin(), tilt_value.end(), [](unsigned char c) { return std::isspace(c); }), tilt_value.end());
  Numbers numbers(tilt_end < text.size() ? text.substr(tilt_end + 1) : std::string(), source);
  double tilt_factor = 1.0;
  if (tilt_value == "INCLUDE") {
    numbers.next("the tilt's lamp-to-luminaire geometry");
    const size_t pairs = numbers.count("the number of tilt angles", 1000);
    std::vector<double> angles(pairs), factors(pairs);
    for (auto& a : angles) a = numbers.next("a tilt angle");
    for (auto& f : factors) {
      f = numbers.next("a tilt multiplying factor");
      if (f < 0) throw InputError(source, "a tilt multiplying factor is negative");
    }
    check_ascending(angles, source, "tilt angles");
    // Mounted as measured: the factor at tilt 0.
    tilt_factor = factors.front();
    for (size_t i = 0; i + 1 < pairs; ++i)
      if (angles[i] <= 0 && angles[i + 1] >= 0) tilt_factor = factors[i] + (factors[i + 1] - factors[i]) * (0 - angles[i]) / (angles[i + 1] - angles[i]);
  } else if (tilt_value != "NONE") {
    throw InputError(source, "TILT=" + tilt_value + ": a separate tilt file is not supported (use TILT=NONE or TILT=INCLUDE)");
  }
  const double lamps = numbers.next("the number of lamps");
  const double lumens_per_lamp = numbers.next("lumens per lamp");
  const double multiplier = numbers.next("the candela multiplier");
  const size_t nv = numbers.count("the number of vertical angles", 100000);
  const size_t nh = numbers.count("the number of horizontal angles", 100000);
  const double type = numbers.next("the photometric type");
  const double units = numbers.next("the units type");
  // The luminous opening: width along C90–C270, length along C0–C180, feet
  // (units 1) or metres; both negative: round (LM-63-2002), diameter |width|.
  const double width = numbers.next("the width"), length = numbers.next("the length");
  numbers.next("the height");
  const double ballast = numbers.next("the ballast factor");
  const double ballast_lamp = numbers.next("the ballast-lamp factor (future use)");
  p.input_watts = std::max(0.0, numbers.next("the input watts"));
  if (type == 3) throw InputError(source, "photometric type A (automotive) is not supported: only types C and B");
  if (type != 1 && type != 2) throw InputError(source, "the photometric type must be 1 (C), 2 (B) or 3 (A), not " + std::to_string(type));
  if (!(multiplier > 0) || !(ballast > 0) || ballast_lamp < 0 || lamps < 0)
    throw InputError(source, "the candela multiplier and ballast factor must be positive, the lamp count not negative");
  if (nv * nh > 4000000) throw InputError(source, "too many angles (" + std::to_string(nv) + " × " + std::to_string(nh) + ")");
  p.type = type == 2 ? Photometry::Type::B : Photometry::Type::C;
  const double metres = units == 1 ? 0.3048 : 1.0;
  if (std::isfinite(width) && std::isfinite(length)) {
    p.opening_round = width < 0 && length < 0;
    p.opening_length = std::abs(length) * metres;
    p.opening_width = std::abs(width) * metres;
  }
  p.rated_lumens = lumens_per_lamp > 0 ? lamps * lumens_per_lamp : 0.0;  // −1: absolute photometry
  p.vertical.resize(nv);
  p.horizontal.resize(nh);
  for (auto& v : p.vertical) v = numbers.next("a vertical angle");
  for (auto& h : p.horizontal) h = numbers.next("a horizontal angle");
  check_ascending(p.vertical, source, "vertical angles");
  check_ascending(p.horizontal, source, "horizontal angles");
  // ballast_lamp is 1 in LM-63-2002 files ("future use"); the 1995 factor.
  const double scale = multiplier * ballast * (ballast_lamp > 0 ? ballast_lamp : 1.0) * tilt_factor;
  p.candela.resize(nv * nh);
  for (size_t k = 0; k < p.candela.size(); ++k) {
    const double c = numbers.next("candela value " + std::to_string(k + 1) + " of " + std::to_string(p.candela.size()));
    if (c < 0) throw InputError(source, "candela value " + std::to_string(k + 1) + " is negative (" + std::to_string(c) + ")");
    p.candela[k] = c * scale;
    if (!(p.candela[k] <= kBrightestCandela)) {
      char text[160];
      std::snprintf(text, sizeof(text), "candela value %zu comes to %.3g cd, beyond any luminaire (at most 1e10 cd)", k + 1, p.candela[k]);
      throw InputError(source, text);
    }
  }
  if (numbers.more()) throw InputError(source, "more numbers than the angle counts say (wrong counts?)");
  const double first = p.horizontal.front(), last = p.horizontal.back();
  if (p.type == Photometry::Type::C) {
    if (p.vertical.front() < 0 || p.vertical.back() > 180) throw InputError(source, "type C vertical angles must lie in 0-180");
    if (nh == 1) p.symmetry = Photometry::Symmetry::Rotational;
    else if (first == 0 && last == 90) p.symmetry = Photometry::Symmetry::Quadrants;
    else if (first == 0 && last == 180) p.symmetry = Photometry::Symmetry::AboutC0C180;
    else if (first == 90 && last == 270) p.symmetry = Photometry::Symmetry::AboutC90C270;
    else if (first == 0 && last == 360) p.symmetry = Photometry::Symmetry::None;
    else throw InputError(source, "type C horizontal angles must run 0, 0-90, 0-180, 90-270 or 0-360, not " + std::to_string(first) + "-" + std::to_string(last));
  } else {
    if (p.vertical.front() < -90 || p.vertical.back() > 90) throw InputError(source, "type B vertical angles must lie in -90-90");
    if (first == 0 && last <= 90) p.symmetry = Photometry::Symmetry::AboutC0C180;  // mirrored left-right
    else if (first >= -90 && last <= 90) p.symmetry = Photometry::Symmetry::None;
    else throw InputError(source, "type B horizontal angles must lie in -90-90");
  }
  return p;
}

} // namespace hilight
