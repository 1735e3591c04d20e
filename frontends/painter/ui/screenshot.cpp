#include "ui/screenshot.hpp"

#include "hilight/io/image_io.hpp"
#include "ui/gl.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace hilight::painter::ui {

namespace {

float srgb_decode(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

} // namespace

Image read_framebuffer(int width, int height) {
  std::vector<unsigned char> bytes(size_t(width) * size_t(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
  std::array<float, 256> linear{};
  for (int i = 0; i < 256; ++i) linear[size_t(i)] = srgb_decode(float(i) / 255.f);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = &bytes[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 3];
      image.at(x, y) = Rgb(linear[p[0]], linear[p[1]], linear[p[2]]);
      image.covered[size_t(y) * size_t(width) + size_t(x)] = 1;  // every pixel is final: no background fill
    }
  return image;
}

void save_screenshot(const std::filesystem::path& path, int width, int height) {
  write_image(path, read_framebuffer(width, height), 1.f);
}

} // namespace hilight::painter::ui
