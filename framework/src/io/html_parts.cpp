// Pieces of the HTML report (html_parts.hpp).
#include "html_parts.hpp"

#include "hilight/io/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <cstdint>
#include <vector>

namespace hilight {

namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0u);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

} // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

std::string png_img(const Image& image, float exposure, const std::string& alt) {
  return "<img alt=\"" + html_escape(alt) + "\" width=\"" + std::to_string(image.width) + "\" src=\"data:image/png;base64," +
         base64(encode_png(image, exposure)) + "\">";
}

float exposure_for(const Image& image) { return auto_exposure(image); }

Rgb false_colour(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const double stops[5][3] = {{0.05, 0.1, 0.5}, {0.0, 0.7, 0.9}, {0.1, 0.8, 0.2}, {1.0, 0.9, 0.0}, {0.9, 0.1, 0.05}};
  const double s = t * 4.0;
  const int k = std::min(3, int(s));
  const double f = s - double(k);
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = float(stops[k][c] * (1 - f) + stops[k + 1][c] * f);
  return out;
}

std::string false_colour_css(double t) {
  const Rgb c = false_colour(t);
  std::ostringstream out;
  out << "rgb(" << int(255.f * c.r) << "," << int(255.f * c.g) << "," << int(255.f * c.b) << ")";
  return out.str();
}

double round_length(double at_most) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(std::max(at_most, 1e-9))));
  double out = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude <= at_most) out = m * magnitude;
  return out;
}

std::vector<double> isoline_levels(double low, double high) {
  std::vector<double> levels;
  if (!(high > low)) return levels;
  const double step = round_length(1.5 * (high - low) / 5.0);
  for (double level = std::ceil(low / step) * step; level < high; level += step) levels.push_back(level);
  return levels;
}

double round_up(double at_least) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(std::max(at_least, 1e-9))));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * magnitude >= at_least) return m * magnitude;
  return 10.0 * magnitude;
}

} // namespace hilight
