#pragma once
// Pieces every part of the HTML report uses (io/html_report.hpp): text
// escaped for HTML, images embedded as PNG data, and the exposure that shows
// an image's bright end without clipping most of it.
#include "hilight/image.hpp"

#include <string>
#include <vector>

namespace hilight {

std::string html_escape(const std::string& text);
/// An <img> holding `image` as base64 PNG data, scaled by `exposure`.
std::string png_img(const Image& image, float exposure, const std::string& alt);
/// auto_exposure (image_io.hpp): each view its own.
float exposure_for(const Image& image);

/// The false colours of lux maps: dark blue → cyan → green → yellow → red
/// over t in [0, 1], as sRGB values in [0, 1].
Rgb false_colour(double t);
/// The same as a CSS colour, "rgb(r,g,b)".
std::string false_colour_css(double t);
/// A round length (1, 2 or 5 × 10^k) no longer than `at_most`.
double round_length(double at_most);
/// Round levels (a step of 1, 2 or 5 × 10^k, about five of them) from `low`
/// up to below `high`: where isolines are drawn. None unless high > low.
std::vector<double> isoline_levels(double low, double high);
/// A round number (1, 2, 2.5, 5 or 10 × 10^k) at least `at_least`: the top of a colour scale.
double round_up(double at_least);

} // namespace hilight
