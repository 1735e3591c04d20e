#pragma once
/// Luminaire photometry files (hilight/photometry.hpp):
/// - IES LM-63 (1986, 1991, 1995, 2002): TILT=NONE and TILT=INCLUDE (the
///   factor at the luminaire's measured tilt, 0°, scales the candela);
///   photometric types C and B (type A is refused); the candela multiplier,
///   ballast factor and ballast-lamp factor applied; symmetric files (one C
///   plane, 0–90°, 0–180°) extended as the standard says.
/// - EULUMDAT (.ldt): Isym 0–4; intensities in cd/klm scaled by the lamps'
///   total flux and the conversion factor.
/// Every problem is an InputError naming the file and what is wrong.
#include "hilight/photometry.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hilight {

/// The brightest luminaire taken, in candela: searchlights reach 10⁹. A
/// file beyond it (3e38 cd was taken, and the solve then asked for "a
/// brighter luminaire") is refused (issue 35).
constexpr double kBrightestCandela = 1e10;

/// By extension: .ies or .ldt (any case).
Photometry read_photometry(const std::filesystem::path& path);
Photometry parse_ies(const std::string& text, const std::string& source);
Photometry parse_ldt(const std::string& text, const std::string& source);

/// The photometry as an IES LM-63-2002 file (type C, metres, one lamp of
/// the rated flux, multiplier 1): the stored planes extended by their
/// symmetry to the full circle (a rotational profile keeps one plane), so a
/// EULUMDAT file reaches tools that read only IES. The candela are
/// hilight's at every node; a type B profile is sampled every 1° by 2.5°.
std::string ies_text(const Photometry& photometry);

/// A product name from a file's fields: each trimmed, control characters
/// and stray bytes dropped, the non-empty ones joined by blanks, at most
/// 200 characters (Photometry::product).
std::string product_text(const std::vector<std::string>& parts);

} // namespace hilight
