// Luminaire photometry (issue 14): IES LM-63 and EULUMDAT files generated
// here (Debian ships none), read back against the analytic intensity and
// flux of each; and the bad-file corpus, one line and exit 2 each.
#include "hilight/error.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/math.hpp"
#include "photometry_files.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

using namespace hilight;

namespace {

using test::angles;

std::string ies(const std::vector<double>& vertical, const std::vector<double>& horizontal,
                const std::function<double(double, double)>& f, int type = 1, const std::string& tilt = "TILT=NONE",
                double multiplier = 1, double ballast = 1) {
  return test::ies_text(vertical, horizontal, f, type, tilt, multiplier, ballast);
}

std::string ldt(int isym, const std::vector<double>& c_angles, const std::vector<double>& gammas,
                const std::vector<std::vector<double>>& planes, double lumens) {
  return test::ldt_text(isym, c_angles, gammas, planes, lumens);
}

} // namespace

TEST_CASE("IES: a constant luminaire gives its candela everywhere and 4π times it in lumens", "[photometry]") {
  const Photometry p = parse_ies(ies(angles(0, 180, 5), {0}, [](double, double) { return 100.0; }), "constant.ies");
  CHECK(p.symmetry == Photometry::Symmetry::Rotational);
  for (double c : {0.0, 37.0, 211.0})
    for (double g : {0.0, 44.0, 90.0, 179.0}) CHECK(p.intensity(c, g) == Approx(100.0));
  CHECK(p.flux() == Approx(4.0 * kPi * 100.0).epsilon(2e-3));
  CHECK(p.rated_lumens == 1000.0);
  CHECK(p.input_watts == 36.0);
  // The multiplier and the ballast factor scale the candela.
  const Photometry scaled = parse_ies(ies(angles(0, 180, 5), {0}, [](double, double) { return 100.0; }, 1, "TILT=NONE", 2.0, 0.9), "scaled.ies");
  CHECK(scaled.intensity(10, 10) == Approx(180.0));
}

TEST_CASE("IES: a quadrant-symmetric downlight mirrors into all four quadrants and integrates to its analytic flux", "[photometry]") {
  // f(C) = 100 + 50 cos 2C on C = 0, 30, 60, 90; nothing above the horizon.
  const auto f = [](double c, double) { return 100.0 + 50.0 * std::cos(2.0 * c * kPi / 180.0); };
  const Photometry p = parse_ies(ies(angles(0, 90, 10), angles(0, 90, 30), f), "quadrants.ies");
  CHECK(p.symmetry == Photometry::Symmetry::Quadrants);
  for (double c : {10.0, 30.0, 45.0, 80.0}) {
    const double base = p.intensity(c, 40);
    CHECK(p.intensity(180 - c, 40) == Approx(base));
    CHECK(p.intensity(180 + c, 40) == Approx(base));
    CHECK(p.intensity(360 - c, 40) == Approx(base));
  }
  CHECK(p.intensity(60, 40) == Approx(f(60, 0)));
  CHECK(p.intensity(0, 120) == 0.0);  // above the measured range: dark
  // ∫ f dC over the circle × ∫ sin γ dγ over 0–90°: the cos 2C part averages out (also piecewise linear).
  CHECK(p.flux() == Approx(2.0 * kPi * 100.0).epsilon(3e-3));
}

TEST_CASE("IES: TILT=INCLUDE scales by the factor at the measured tilt, and type B is looked up through B to C", "[photometry]") {
  const std::string tilt = "TILT=INCLUDE\n1\n3\n0 45 90\n0.8 0.7 0.6";
  const Photometry tilted = parse_ies(ies(angles(0, 180, 10), {0}, [](double, double) { return 100.0; }, 1, tilt), "tilt.ies");
  CHECK(tilted.intensity(0, 30) == Approx(80.0));
  // Type B: a 10° beam around the photometric axis (H = V = 0, the nadir here).
  const auto beam = [](double h, double v) { return std::abs(h) <= 10 && std::abs(v) <= 10 ? 1000.0 : 0.0; };
  const Photometry b = parse_ies(ies(angles(-90, 90, 5), angles(-90, 90, 5), beam, 2), "floodlight.ies");
  CHECK(b.type == Photometry::Type::B);
  CHECK(b.intensity(0, 0) == Approx(1000.0));
  CHECK(b.intensity(0, 5) == Approx(1000.0));   // H = 5, V = 0
  CHECK(b.intensity(90, 5) == Approx(1000.0));  // H = 0, V = 5
  CHECK(b.intensity(0, 60) == 0.0);             // H = 60
  CHECK(b.intensity(90, 60) == 0.0);            // V = 60
  // Its flux: the beam's solid angle in (H, V): ∫∫ cos V dH dV over |H|, |V| ≤ 10° (plus the interpolated rim).
  const double core = 1000.0 * (20.0 * kPi / 180.0) * 2.0 * std::sin(10.0 * kPi / 180.0);
  CHECK(b.flux() > core);
  CHECK(b.flux() < 1000.0 * (30.0 * kPi / 180.0) * 2.0 * std::sin(15.0 * kPi / 180.0));
}

TEST_CASE("EULUMDAT: Isym 1 in cd/klm scaled by the lamps' flux, and Isym 4 mirrored", "[photometry]") {
  const auto gammas = angles(0, 180, 10);
  const Photometry round = parse_ldt(ldt(1, angles(0, 345, 15), gammas, {std::vector<double>(gammas.size(), 200.0)}, 2000), "round.ldt");
  CHECK(round.symmetry == Photometry::Symmetry::Rotational);
  CHECK(round.intensity(77, 33) == Approx(400.0));  // 200 cd/klm × 2 klm
  CHECK(round.flux() == Approx(4.0 * kPi * 400.0).epsilon(2e-3));
  CHECK(round.rated_lumens == 2000.0);
  CHECK(round.input_watts == 25.0);
  // Isym 4: planes C0-C90 stored (7 of 24), the rest mirrored.
  std::vector<std::vector<double>> planes;
  for (double c : angles(0, 90, 15)) planes.push_back(std::vector<double>(gammas.size(), 100.0 + c));
  const Photometry quad = parse_ldt(ldt(4, angles(0, 345, 15), gammas, planes, 1000), "quad.ldt");
  CHECK(quad.symmetry == Photometry::Symmetry::Quadrants);
  CHECK(quad.intensity(30, 50) == Approx(130.0));
  CHECK(quad.intensity(150, 50) == Approx(130.0));
  CHECK(quad.intensity(210, 50) == Approx(130.0));
  CHECK(quad.intensity(330, 50) == Approx(130.0));
}

TEST_CASE("bad photometry files are refused in one line naming the file, exit 2", "[photometry][bad-input]") {
  const auto dir = test::output_dir("photometry_bad");
  const auto one = [](double, double) { return 10.0; };
  const std::string good = ies(angles(0, 90, 30), {0}, one);
  std::vector<std::pair<std::string, std::string>> cases = {
      {"truncated.ies", good.substr(0, good.size() - 12)},
      {"extra.ies", good + "5 5 5\n"},
      {"negative.ies", ies(angles(0, 90, 30), {0}, [](double, double v) { return v == 30 ? -1.0 : 1.0; })},
      {"type-a.ies", ies(angles(0, 90, 30), {0}, one, 3)},
      {"tilt-file.ies", ies(angles(0, 90, 30), {0}, one, 1, "TILT=lamp.tlt")},
      {"no-tilt.ies", "IESNA:LM-63-2002\n[TEST] x\n1 1000 1 1 1 1 2 0 0 0\n1 1 1\n0\n0\n5\n"},
      {"descending.ies", ies({0, 60, 30}, {0}, one)},
      {"not-a-number.ies", ies(angles(0, 90, 30), {0}, one).replace(good.find("1 1000"), 6, "1 many")},
      {"truncated.ldt", ldt(1, {0}, angles(0, 180, 90), {{1, 2, 3}}, 1000).substr(0, 120)},
      {"negative.ldt", ldt(1, {0}, angles(0, 180, 90), {{1, -2, 3}}, 1000)},
      {"no-flux.ldt", ldt(1, {0}, angles(0, 180, 90), {{1, 2, 3}}, 0)},
      // A C angle past a turn (the fuzzer's: planes at 510 and 870, read as if at 150 and 150).
      {"c-past-360.ldt", ldt(0, {510, 870}, angles(0, 180, 90), {{1, 2, 3}, {1, 2, 3}}, 1000)},
      // Isym 2 (C0-C180 mirrored) with planes only from 0.5 to 5: nothing to mirror between 5 and 175.
      {"half-planes.ldt", ldt(2, {0.5, 5}, angles(0, 180, 90), {{1, 2, 3}, {1, 2, 3}}, 1000)},
      {"wrong.txt", good}};
  for (const auto& [name, text] : cases) {
    INFO(name);
    std::ofstream(dir / name) << text;
    CHECK_THROWS_AS(read_photometry(dir / name), InputError);
    const auto r = test::run_hilight({"luminaire", (dir / name).string()});
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(name));
    CHECK(r.out.empty());
  }
  std::ofstream(dir / "good.ies") << good;
  const auto ok = test::run_hilight({"luminaire", (dir / "good.ies").string()});
  CHECK(ok.exit_code == 0);
  CHECK_THAT(ok.out, Catch::Contains("\"flux_lm\""));
}

// Issue 37: a EULUMDAT luminaire reaches Cycles, which reads only IES, as an
// IES file hilight writes (`hilight luminaire F.ldt --ies F.ies`). Each
// symmetry, with a profile that tells every plane apart that the symmetry
// allows, written and read back: the same candela at angles off the nodes,
// the same flux, rated lumens, watts and opening.
TEST_CASE("EULUMDAT of every symmetry written as IES reads back with the same candela everywhere", "[photometry][ies-writer]") {
  const auto gammas = angles(0, 180, 7.5), c_all = angles(0, 345, 15);
  struct Case {
    int isym;
    std::function<double(double, double)> f;  // cd/klm at (C, γ), in degrees
  };
  const double d = kPi / 180.0;
  const std::vector<Case> cases = {
      {0, [d](double c, double g) { return 120.0 + 80.0 * std::cos(g * d) + 30.0 * std::sin(c * d) * std::sin(g * d) + 0.1 * c; }},
      {1, [d](double, double g) { return 150.0 + 100.0 * std::cos(g * d); }},
      {2, [d](double c, double g) { return 120.0 + 60.0 * std::cos(c * d) * std::sin(g * d) + 20.0 * std::cos(g * d); }},
      {3, [d](double c, double g) { return 120.0 + 60.0 * std::sin(c * d) * std::sin(g * d) + 20.0 * std::cos(g * d); }},
      {4, [d](double c, double g) { return 120.0 + 50.0 * std::cos(2.0 * c * d) * std::sin(g * d) + 10.0 * std::cos(g * d); }}};
  for (const Case& k : cases) {
    INFO("Isym " << k.isym);
    std::vector<std::vector<double>> planes;
    for (double c : c_all) {
      const bool stored = k.isym == 0 || (k.isym == 2 && c <= 180) || (k.isym == 3 && c >= 90 && c <= 270) || (k.isym == 4 && c <= 90);
      if (k.isym == 1 ? planes.empty() : stored) {
        std::vector<double> plane;
        for (double g : gammas) plane.push_back(k.f(c, g));
        planes.push_back(plane);
      }
    }
    const Photometry ldt_profile = parse_ldt(ldt(k.isym, c_all, gammas, planes, 3000), "profile.ldt");
    const std::string text = ies_text(ldt_profile);
    const Photometry back = parse_ies(text, "profile.ies");
    CHECK(back.type == Photometry::Type::C);
    CHECK(back.rated_lumens == Approx(ldt_profile.rated_lumens));
    CHECK(back.input_watts == Approx(ldt_profile.input_watts));
    CHECK(back.flux() == Approx(ldt_profile.flux()).epsilon(1e-6));
    double worst = 0;
    for (double c = 0.0; c < 360.0; c += 11.3)
      for (double g = 0.0; g <= 180.0; g += 6.1) {
        const double want = ldt_profile.intensity(c, g);
        worst = std::max(worst, std::abs(back.intensity(c, g) - want) / want);
      }
    CHECK(worst < 1e-6);
    // At every node the file states the analytic value (3 klm: cd/klm × 3;
    // the EULUMDAT text keeps 6 digits), the symmetry applied.
    for (double c : c_all)
      for (double g : gammas) {
        const double analytic = k.isym == 1 ? k.f(0.0, g) : k.f(c, g);
        CHECK(back.intensity(c, g) == Approx(3.0 * analytic).epsilon(2e-5));
      }
  }
}

TEST_CASE("hilight luminaire --ies writes an IES file that reads back, and refuses another extension", "[photometry][ies-writer][cli]") {
  const auto dir = test::output_dir("photometry_ies_out");
  const auto gammas = angles(0, 180, 10);
  std::vector<std::vector<double>> planes;
  for (double c : angles(0, 90, 15)) planes.push_back(std::vector<double>(gammas.size(), 100.0 + c));
  std::ofstream(dir / "quad.ldt") << ldt(4, angles(0, 345, 15), gammas, planes, 1000);
  std::filesystem::remove(dir / "quad.ies");
  const auto r = test::run_hilight({"luminaire", (dir / "quad.ldt").string(), "--ies", (dir / "quad.ies").string()});
  REQUIRE(r.exit_code == 0);
  const Photometry in = read_photometry(dir / "quad.ldt"), out = read_photometry(dir / "quad.ies");
  CHECK(out.peak() == Approx(in.peak()));
  CHECK(out.intensity(150, 50) == Approx(in.intensity(150, 50)));
  CHECK(out.intensity(250, 75) == Approx(in.intensity(250, 75)));
  const auto bad = test::run_hilight({"luminaire", (dir / "quad.ldt").string(), "--ies", (dir / "quad.txt").string()});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
  CHECK_THAT(bad.err, Catch::Contains("quad.txt"));
  CHECK(!std::filesystem::exists(dir / "quad.txt"));
}

// Found by the photometry fuzzer's IES round trip: a EULUMDAT file of Isym 0
// whose planes start past C = 0 read 0 cd between C = 0 and its first plane,
// though after its last plane it wrapped round to the first. Both sides of
// C = 0 now lie between the last plane and the first, a turn apart.
TEST_CASE("EULUMDAT planes that start past C = 0 wrap round to the last plane before the first", "[photometry]") {
  const auto gammas = angles(0, 180, 90);
  // Planes at C = 30 and C = 210 (Isym 0, 2 of them, 180 apart): 100 and 300 cd/klm.
  std::string text = ldt(0, {30, 210}, gammas, {{100, 100, 100}, {300, 300, 300}}, 1000);
  const Photometry p = parse_ldt(text, "late-planes.ldt");
  REQUIRE(p.horizontal.front() == 30.0);
  // C = 0 lies 150° after the last plane (210), 30° before the first: 5/6 of the way from 300 to 100.
  CHECK(p.intensity(0, 0) == Approx(300.0 + (100.0 - 300.0) * 150.0 / 180.0));
  CHECK(p.intensity(15, 0) == Approx(300.0 + (100.0 - 300.0) * 165.0 / 180.0));
  CHECK(p.intensity(359, 0) == Approx(p.intensity(-1, 0)));
  CHECK(p.intensity(30, 0) == Approx(100.0));
  CHECK(p.intensity(120, 0) == Approx(200.0));
  // And its IES text reads back the same all round.
  const Photometry back = parse_ies(ies_text(p), "late-planes.ies");
  for (double c = 0; c < 360; c += 7.5) CHECK(back.intensity(c, 45) == Approx(p.intensity(c, 45)));
}
