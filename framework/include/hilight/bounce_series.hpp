#pragma once
/// The sum of the light bounced again and again, f = d₁ + d₂ + …, and when it
/// ends: one rule for every renderer that carries every bounce (Embree's
/// vertex transport, ism-vulkan's bounce points; docs/rendering-model.md,
/// "Every bounce"). Each light's series ends when a step is negligible
/// against its sum (kNegligible, per channel), at the count asked for, or,
/// for "all", once successive steps shrink by a steady ratio r
/// (kSteadyRatio) and the geometric rest d_k·r/(1−r) is a small share of the
/// sum (kRestShare), with that rest added: a bright room converges as ρ^k,
/// so ρ = 0.95 would take ~180 steps to 10⁻⁴ without it.
#include "hilight/bounces.hpp"
#include "hilight/math.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hilight {

class BounceSeriesSum {
public:
  static constexpr double kNegligible = 1e-5;   ///< a step this small of the sum ends the series
  static constexpr double kSteadyRatio = 2e-3;  ///< ratios of successive steps this close: the geometric rest is added
  /// ... once the rest is at most this share of the sum: the rest takes the
  /// last step's shape, which the tail has only once the slowest mode leads.
  /// In the bundled room the ratio was steady at the 4th step, the rest 15%
  /// of the light, and it put 1% of the vertices 14% or more (up to 53%)
  /// from the series summed out; with 2% every lit vertex came within 5.2%,
  /// with 1% within 3.0% (tests/test_cie171.cpp).
  static constexpr double kRestShare = 0.01;

  /// How a step's values lie: a light's n values together, or the lights'
  /// values of one entry together (what a walk over entries reads best).
  enum class Layout { LightMajor, EntryMajor };

  /// `lights` series of `n` values each; `bounces`: the total count (≥ 2)
  /// or kAllBounces, which stops by `most_steps` at the latest.
  /// `rest_share`: kRestShare, or a renderer's own (a fast twin's looser
  /// one); the ratios' steadiness is asked in proportion (kSteadyRatio at
  /// kRestShare).
  BounceSeriesSum(size_t lights, size_t n, int bounces, int most_steps, Layout layout = Layout::LightMajor,
                  double rest_share = kRestShare)
      : m_n(n), m_lights(lights), m_all(bounces == kAllBounces), m_last(m_all ? most_steps : bounces - 1), m_rest_share(rest_share),
        m_steady_ratio(kSteadyRatio * rest_share / kRestShare),
        m_entry_stride(layout == Layout::EntryMajor ? lights : 1), m_light_stride(layout == Layout::EntryMajor ? 1 : n),
        m_sum(lights * n, Rgb(0.f)), m_active(lights, 1), m_previous_ratio(lights, {-1.0, -1.0, -1.0}), m_previous_size(lights) {}

  /// Adds step `step` (d_step, counted from 1; in the sums' layout) to each
  /// active light's sum and ends the series that are done. False once none
  /// is active.
  bool add(int step, const std::vector<Rgb>& current) {
    // One pass over the entries for every light (entry-major, the lights of
    // an entry lie together): the step joins the sums, and the step's and the
    // sums' totals per channel, in double, are summed in entry order.
    std::vector<std::array<double, 3>> size(m_lights, {0.0, 0.0, 0.0}), total(m_lights, {0.0, 0.0, 0.0});
    for (size_t k = 0; k < m_n; ++k)
      for (size_t j = 0; j < m_lights; ++j) {
        if (!m_active[j]) continue;
        const size_t at = k * m_entry_stride + j * m_light_stride;
        const Rgb d = current[at];
        Rgb& s = m_sum[at];
        s += d;
        for (int c = 0; c < 3; ++c) {
          size[j][c] += double(d[c]);
          total[j][c] += double(s[c]);
        }
      }
    std::vector<Rgb> rest(m_lights, Rgb(0.f));
    bool any_rest = false;
    for (size_t j = 0; j < m_lights; ++j) {
      if (!m_active[j]) continue;
      std::array<double, 3> ratio{-1.0, -1.0, -1.0};
      bool negligible = true, steady = step >= 3;
      Rgb r(0.f);
      for (int c = 0; c < 3; ++c) {
        if (step > 1 && m_previous_size[j][c] > 0.0) ratio[c] = size[j][c] / m_previous_size[j][c];
        if (size[j][c] <= kNegligible * total[j][c]) continue;  // this channel has converged
        negligible = false;
        steady = steady && ratio[c] > 0.0 && ratio[c] < 1.0 && std::abs(ratio[c] - m_previous_ratio[j][c]) <= m_steady_ratio &&
                 size[j][c] * ratio[c] / (1.0 - ratio[c]) <= m_rest_share * total[j][c];
        if (steady) r[c] = float(ratio[c] / (1.0 - ratio[c]));
      }
      bool done = negligible || step >= m_last;
      if (m_all && !done && steady) {
        rest[j] = r;  // the geometric rest, per channel: d_k (r + r² + …) = d_k r/(1−r)
        any_rest = true;
        done = true;
      }
      if (done) m_active[j] = 0;
      m_previous_ratio[j] = ratio;
      m_previous_size[j] = size[j];
    }
    if (any_rest)
      for (size_t k = 0; k < m_n; ++k)
        for (size_t j = 0; j < m_lights; ++j) {
          if (rest[j] == Rgb(0.f)) continue;
          const size_t at = k * m_entry_stride + j * m_light_stride;
          m_sum[at] += current[at] * rest[j];
        }
    return std::any_of(m_active.begin(), m_active.end(), [](char a) { return a != 0; });
  }

  /// Per light, whether its series goes on (the next step is needed).
  const std::vector<char>& active() const { return m_active; }
  std::vector<Rgb>& sum() { return m_sum; }

private:
  size_t m_n, m_lights;
  bool m_all;
  int m_last;
  double m_rest_share, m_steady_ratio;
  size_t m_entry_stride, m_light_stride;  ///< from one entry, one light to the next
  std::vector<Rgb> m_sum;
  std::vector<char> m_active;
  std::vector<std::array<double, 3>> m_previous_ratio, m_previous_size;
};

} // namespace hilight
