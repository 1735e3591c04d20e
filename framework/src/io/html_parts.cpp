// Pieces of the HTML report (html_parts.hpp).
#include "html_parts.hpp"

#include "hilight/io/image_io.hpp"

#include <algorithm>
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

} // namespace hilight
