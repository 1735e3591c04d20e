#pragma once
/// Screenshots: the window's back buffer as written to screen, saved as PNG
/// through the framework's image writer (atomic, sRGB-tagged).
#include "hilight/image.hpp"

#include <filesystem>

namespace hilight::painter::ui {

/// Reads the current framebuffer (bottom-up in GL) into a top-down image of
/// linear values that re-encode to exactly the displayed sRGB bytes.
Image read_framebuffer(int width, int height);

/// read_framebuffer + write_image with exposure 1 (the pixels are final).
void save_screenshot(const std::filesystem::path& path, int width, int height);

} // namespace hilight::painter::ui
