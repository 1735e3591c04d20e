#pragma once
/// A linear RGB float image, row-major, top row first.
#include "hilight/math.hpp"

#include <vector>

namespace hilight {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;
  std::vector<unsigned char> covered; ///< 1 where a primary ray hit the scene

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(size_t(w) * h, Rgb(0.f)), covered(size_t(w) * h, 0) {}
  Rgb& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const Rgb& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

} // namespace hilight
