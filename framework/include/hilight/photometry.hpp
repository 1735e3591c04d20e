#pragma once
/// A luminaire's light distribution (photometry): candela over a grid of
/// angles, read from an IES LM-63 or EULUMDAT file (io/photometry_io.hpp).
/// Angles are type C: γ from the nadir (the luminaire's aim, straight down
/// when mounted as measured), C the plane around it, counter-clockwise from
/// the luminaire's length axis seen from above. A type B file keeps its own
/// grid and is looked up through the B↔C conversion. The shape is fixed and
/// scaled by dimming, so a light with a profile stays linear in intensity.
#include <string>
#include <vector>

namespace hilight {

struct Photometry {
  enum class Type { C, B };
  /// How the stored planes extend to the full circle.
  enum class Symmetry { None, Rotational, AboutC0C180, AboutC90C270, Quadrants };

  std::string source;       ///< file, for messages
  Type type = Type::C;
  Symmetry symmetry = Symmetry::None;
  std::vector<double> vertical;    ///< γ (type C) or V (type B), degrees, ascending
  std::vector<double> horizontal;  ///< C (type C) or H (type B) of the stored planes, degrees, ascending
  std::vector<double> candela;     ///< [plane * vertical.size() + i], at the rated lamp output
  double rated_lumens = 0;  ///< the lamps' rated flux (0: absolute photometry, see flux())
  double input_watts = 0;   ///< electrical input, 0 when the file does not say
  /// The luminous opening the file gives, metres: `opening_length` along
  /// C0–C180 (a disk's diameter when `opening_round`), `opening_width` along
  /// C90–C270; 0 × 0 for a point source.
  double opening_length = 0, opening_width = 0;
  bool opening_round = false;
  /// The luminaire's body, metres, as the opening's (EULUMDAT gives it; an
  /// IES file gives only the opening): what must not overlap another's.
  double body_length = 0, body_width = 0;
  bool body_round = false;
  /// What the file names the luminaire (IES [MANUFAC] [LUMINAIRE]
  /// [LUMCAT]; EULUMDAT's company, name and number), printable text only,
  /// for schedules; empty when it names none.
  std::string product;

  /// Candela towards (C, γ) in degrees (type C angles whatever the file's type):
  /// bilinear in the stored grid, 0 outside the measured range.
  double intensity(double c_deg, double gamma_deg) const;
  /// Luminous flux in lumens: the candela integrated over the sphere.
  double flux() const;
  /// The largest candela value.
  double peak() const;
};

/// Turns about the aim (degrees, from 0) that the profile's symmetry tells
/// apart: one for a rotational profile, 0 and 90 for one symmetric in its
/// quadrants, else 0, 90, 180 and 270. The solves try these.
std::vector<float> distinct_spins(const Photometry& profile);

} // namespace hilight
