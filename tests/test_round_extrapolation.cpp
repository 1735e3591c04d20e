// RoundExtrapolation (solve/round_extrapolation.hpp): rounds that each close
// a steady share of the gap to their fixed point are carried to it; rounds
// that turn, grow or change their lights are not.
#include "hilight/solve/round_extrapolation.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {

Lighting spot_and_lamp(const Vec3& spot_at, const Vec3& aim, float cutoff, const Vec3& lamp_at) {
  Light spot;
  spot.type = LightType::Spot;
  spot.position = spot_at, spot.direction = glm::normalize(aim), spot.cutoff_deg = cutoff, spot.falloff_deg = 5.f;
  Light lamp;
  lamp.position = lamp_at;
  return {spot, lamp};
}

/// A round of a linear fixed-point iteration: the gap to `end` times r.
Lighting round_toward(const Lighting& at, const Lighting& end, float r) {
  Lighting next = at;
  for (size_t j = 0; j < at.size(); ++j) {
    next[j].position = end[j].position + r * (at[j].position - end[j].position);
    next[j].direction = glm::normalize(end[j].direction + r * (at[j].direction - end[j].direction));
    next[j].cutoff_deg = end[j].cutoff_deg + r * (at[j].cutoff_deg - end[j].cutoff_deg);
    next[j].falloff_deg = end[j].falloff_deg + r * (at[j].falloff_deg - end[j].falloff_deg);
  }
  return next;
}

} // namespace

TEST_CASE("round extrapolation: steady rounds are carried to their fixed point", "[solve][extrapolation]") {
  const Lighting end = spot_and_lamp({1.f, 2.9f, 1.f}, {0.f, -1.f, 0.f}, 30.f, {3.f, 2.8f, 2.f});
  const Lighting start = spot_and_lamp({1.2f, 2.85f, 0.9f}, {0.f, -1.f, 0.f}, 32.f, {3.1f, 2.75f, 2.1f});
  for (const float r : {0.5f, 0.8f, 0.9f}) {
    INFO("each round closes " << 1.f - r << " of the gap");
    RoundExtrapolation extrapolation(10.f);
    const Lighting first = round_toward(start, end, r), second = round_toward(first, end, r);
    CHECK_FALSE(extrapolation.ahead(start, first));  // one step tells no ratio
    const std::optional<Lighting> guess = extrapolation.ahead(first, second);
    REQUIRE(guess);
    // Two rounds went (1 − r²) of the way; the guess goes (nearly) all of it.
    for (size_t j = 0; j < end.size(); ++j) {
      CHECK(glm::length(guess->at(j).position - end[j].position) < 1e-4f * glm::length(start[j].position - end[j].position) + 1e-6f);
      CHECK(guess->at(j).type == end[j].type);
    }
    CHECK(guess->at(0).cutoff_deg == Approx(end[0].cutoff_deg).margin(1e-3));
    CHECK(guess->at(0).intensity == second[0].intensity);
  }
}

namespace {

/// The guess after two plain rounds a → b → c, from a fresh RoundExtrapolation.
std::optional<Lighting> guess_after(const Lighting& a, const Lighting& b, const Lighting& c) {
  RoundExtrapolation extrapolation(10.f);
  extrapolation.ahead(a, b);
  return extrapolation.ahead(b, c);
}

} // namespace

TEST_CASE("round extrapolation: rounds that turn, grow or change their lights are left alone", "[solve][extrapolation]") {
  const Lighting a = spot_and_lamp({1.f, 2.9f, 1.f}, {0.f, -1.f, 0.f}, 30.f, {3.f, 2.8f, 2.f});
  Lighting b = a, c = a;
  b[1].position.x += 0.1f;
  SECTION("a turn") {
    c = b, c[1].position.z += 0.1f;  // at right angles to the last step
    CHECK_FALSE(guess_after(a, b, c));
  }
  SECTION("a step that grows") {
    c = b, c[1].position.x += 0.2f;
    CHECK_FALSE(guess_after(a, b, c));
  }
  SECTION("a step back") {
    c = b, c[1].position.x -= 0.05f;
    CHECK_FALSE(guess_after(a, b, c));
  }
  SECTION("other lights") {
    c = b, c[0].type = LightType::Point;
    CHECK_FALSE(guess_after(a, b, c));
  }
  SECTION("a restart forgets the last step") {
    c = b, c[1].position.x += 0.05f;
    RoundExtrapolation extrapolation(10.f);
    extrapolation.ahead(a, b);
    extrapolation.restart();
    CHECK_FALSE(extrapolation.ahead(b, c));
    Lighting d = c;
    d[1].position.x += 0.025f;
    CHECK(extrapolation.ahead(c, d));  // r = 0.5: two rounds more
  }
  SECTION("the furthest guess is ten steps") {
    c = b, c[1].position.x += 0.099f;  // r = 0.99
    const std::optional<Lighting> guess = guess_after(a, b, c);
    REQUIRE(guess);
    CHECK(guess->at(1).position.x == Approx(b[1].position.x + 10 * 0.099f).epsilon(1e-5));
  }
}
