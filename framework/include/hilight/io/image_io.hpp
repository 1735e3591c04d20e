#pragma once
/// Image files: OpenEXR (linear half float) and PNG (tone-mapped sRGB).
#include "hilight/image.hpp"

#include <filesystem>
#include <vector>

namespace hilight {

/// Writes by extension: .exr linear, .png tone-mapped. `exposure` scales
/// radiance before PNG encoding; <= 0 picks one for this image (auto_exposure).
void write_image(const std::filesystem::path& path, const Image& image, float exposure = 0.f);
Image read_exr(const std::filesystem::path& path);
/// The PNG write_image would write, as bytes (for pages that embed images).
std::vector<unsigned char> encode_png(const Image& image, float exposure = 0.f);

/// The exposure that shows this image (each view its own, issue 36): the
/// 99th percentile of the covered pixels' luminance at 0.9, raised where
/// that leaves the median darker than 0.1 (a lamp's hot spot taking the
/// top percent), as far as 5% of the pixels may clip. 1 with nothing lit.
float auto_exposure(const Image& image);

/// A PNG's 8-bit sRGB pixels, row by row (for tests and tools that judge
/// what a person would see). Throws InputError on anything but a PNG.
struct PngPixels {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  ///< 3 per pixel
};
PngPixels read_png(const std::filesystem::path& path);

} // namespace hilight
