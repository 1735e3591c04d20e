#pragma once
// Pieces every part of the HTML report uses (io/html_report.hpp): text
// escaped for HTML, images embedded as PNG data, and the exposure that shows
// an image's bright end without clipping most of it.
#include "hilight/image.hpp"

#include <string>

namespace hilight {

std::string html_escape(const std::string& text);
/// An <img> holding `image` as base64 PNG data, scaled by `exposure`.
std::string png_img(const Image& image, float exposure, const std::string& alt);
/// auto_exposure (image_io.hpp): each view its own.
float exposure_for(const Image& image);

} // namespace hilight
