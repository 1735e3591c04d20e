#pragma once
/// Where rounds of "refine with the bounce held, re-take the bounce" are
/// heading. Each such round moves the lights only part of the way toward the
/// lights whose own bounce they fit: the held bounce pulls them back toward
/// where it was taken. The steps then point the same way and shrink by a
/// steady ratio r (measured on the curved models' spot: r ≈ 0.7–0.9, twelve
/// rounds for 10⁻⁵ of the size), and the rounds' fixed point lies near
/// x + Δ/(1 − r): Aitken's Δ² along the last step. The caller judges the
/// guess by its own objective and falls back to the plain round.
#include "hilight/lighting.hpp"

#include <optional>
#include <vector>

namespace hilight {

class RoundExtrapolation {
public:
  /// `diagonal`: the scene's, the unit of a position's step.
  explicit RoundExtrapolation(float diagonal) : m_diagonal(diagonal) {}

  /// A plain round took `from` to `to` (the same lights, kinds and order).
  /// The guess of where the rounds end when this step and the one before
  /// point the same way and shrink steadily; nothing otherwise. The guess
  /// keeps `to`'s intensities and is not placed by any rule: the caller places it.
  std::optional<Lighting> ahead(const Lighting& from, const Lighting& to);
  /// The next step is not one plain round after the last (a jump was taken
  /// or refused, or the rounds changed what they fit): forget the last step.
  void restart() { m_last.clear(); }

private:
  float m_diagonal;
  std::vector<double> m_last;  ///< the last plain step, in step units
};

} // namespace hilight
