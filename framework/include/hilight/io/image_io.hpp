#pragma once
/// Image files: OpenEXR (linear half float) and PNG (tone-mapped sRGB).
#include "hilight/image.hpp"

#include <filesystem>
#include <vector>

namespace hilight {

/// Writes by extension: .exr linear, .png tone-mapped. `exposure` scales
/// radiance before PNG encoding; <= 0 picks one so the 99th percentile of
/// covered pixels' luminance maps to 0.9.
void write_image(const std::filesystem::path& path, const Image& image, float exposure = 0.f);
Image read_exr(const std::filesystem::path& path);
/// The PNG write_image would write, as bytes (for pages that embed images).
std::vector<unsigned char> encode_png(const Image& image, float exposure = 0.f);

} // namespace hilight
