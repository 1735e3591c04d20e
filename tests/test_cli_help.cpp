// Help for people (issue 36 item 4): each command's help leads with what a
// user needs and keeps the paper's parameters under "Advanced"; every
// --place form the parser takes is listed; a misspelled option or command
// gets the nearest one; the exit codes are in --help; an output extension a
// command does not write is refused; a lights file states its intensity unit
// and is read in it.
#include "hilight/error.hpp"
#include "hilight/io/lights_file.hpp"
#include "hilight/io/lights_json.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using namespace hilight;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-4lights.json";

/// One line on stderr, exit 2, nothing on stdout: how bad input is said.
void check_one_line_error(const test::RunResult& r) {
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK(r.out.empty());
}

} // namespace

TEST_CASE("Help: solve leads with what a user needs, the paper's parameters under Advanced", "[cli][help]") {
  const test::RunResult r = test::run_hilight({"solve", "--help"});
  REQUIRE(r.exit_code == 0);
  const std::string& help = r.out;
  const size_t advanced = help.find("\nAdvanced");
  REQUIRE(advanced != std::string::npos);
  const std::string main = help.substr(0, advanced), rest = help.substr(advanced);
  // What a user needs, in the main part, the target and the output first.
  for (const char* option : {"--target", "-o,--output", "--lights", "--place", "--luminaire", "--units", "--report-html", "--mode",
                             "--max-dbar", "--bounces", "--progress"})
    CHECK_THAT(main, Contains(option));
  CHECK(main.find("\n  --target ") < main.find("\n  --place "));
  CHECK(main.find("\n  -o,--output ") < main.find("\n  --luminaire "));
  // The paper's parameters and the tuning, only under Advanced.
  for (const char* option : {"--n-cut", "--eps-opt", "--eps-impro", "--weak-threshold", "--seed-cells", "--optimizer", "--sampler",
                             "--samples", "--cache-setting", "--max-edge", "--bounce-samples", "--set"}) {
    INFO(option);
    CHECK(main.find(std::string(option) + " ") == std::string::npos);
    CHECK_THAT(rest, Contains(option));
  }
  CHECK(main.find("ε") == std::string::npos);
  CHECK(main.find("N_cut") == std::string::npos);
}

TEST_CASE("Help: every --place form the parser takes is listed in solve --help", "[cli][help]") {
  // The parser's own list, from its refusal of a rule it does not know.
  const test::RunResult bad = test::run_hilight({"solve", kRoom, "--target", "t.ply", "-o", "l.json", "--place", "nowhere:1"});
  check_one_line_error(bad);
  std::smatch list;
  REQUIRE(std::regex_search(bad.err, list, std::regex("unknown rule \\((.*)\\)")));
  std::vector<std::string> kinds;
  const std::string forms = list[1];
  const std::regex kind_word("(^|, )([a-z-]+)");
  for (auto it = std::sregex_iterator(forms.begin(), forms.end(), kind_word); it != std::sregex_iterator(); ++it)
    kinds.push_back((*it)[2]);
  REQUIRE(kinds.size() >= 7);  // ceiling height box exclude count region not-region
  const std::string help = test::run_hilight({"solve", "--help"}).out;
  const size_t at = help.find("--place");
  REQUIRE(at != std::string::npos);
  const std::string place = help.substr(at, help.find('\n', at) - at);
  for (const auto& kind : kinds) {
    INFO(kind);
    CHECK(std::regex_search(place, std::regex("(^|[ ,(])" + kind + "([:\\[]|( \\())")));  // with its arguments, or `anywhere (...)`
  }
}

TEST_CASE("Help: the exit codes are listed in --help", "[cli][help]") {
  const std::string solve = test::run_hilight({"solve", "--help"}).out;
  for (const char* code : {"0 done", "2 bad input", "3 the result misses", "130 interrupted"}) CHECK_THAT(solve, Contains(code));
  for (const char* command : {"render", "export", "target", "info", "luminaire", "cache", "plugins", "bench"}) {
    INFO(command);
    const test::RunResult r = test::run_hilight({command, "--help"});
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("Exit codes: 0 done; 2 bad input") && Contains("130 interrupted"));
  }
}

TEST_CASE("Help: a misspelled option or command gets the nearest one, in one line, exit 2", "[cli][help][bad-input]") {
  const test::RunResult swapped = test::run_hilight({"solve", kRoom, "--target", "t.ply", "-o", "l.json", "--lihgts", "3"});
  check_one_line_error(swapped);
  CHECK_THAT(swapped.err, Contains("unknown option --lihgts; did you mean --lights?"));
  // Said before the requirement it may have caused (--target is required).
  const test::RunResult required = test::run_hilight({"solve", kRoom, "--targte", "t.ply", "-o", "l.json"});
  check_one_line_error(required);
  CHECK_THAT(required.err, Contains("did you mean --target?"));
  const test::RunResult render = test::run_hilight({"render", kRoom, "--light", kRoomLights, "-o", "x.png"});
  check_one_line_error(render);
  CHECK_THAT(render.err, Contains("did you mean --lights?"));
  const test::RunResult with_value = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", "x.png", "--widht=100"});
  check_one_line_error(with_value);
  CHECK_THAT(with_value.err, Contains("unknown option --widht; did you mean --width?"));
  // Nothing near: the help is named instead.
  const test::RunResult far = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", "x.png", "--zzzzzzzz"});
  check_one_line_error(far);
  CHECK_THAT(far.err, Contains("unknown option --zzzzzzzz (render --help lists the options)"));
  const test::RunResult command = test::run_hilight({"slove", kRoom});
  check_one_line_error(command);
  CHECK_THAT(command.err, Contains("unknown command 'slove'; did you mean 'solve'?"));
}

TEST_CASE("Help: an output extension a command does not write is refused, naming the file", "[cli][help][bad-input]") {
  const fs::path dir = test::output_dir("help_output_types");
  const fs::path text = dir / "x.txt";
  const test::RunResult solve = test::run_hilight({"solve", kRoom, "--target", (dir / "t.ply").string(), "-o", text.string()});
  check_one_line_error(solve);
  CHECK_THAT(solve.err, Contains(text.string() + ": unknown output type '.txt'") && Contains(".json"));
  const test::RunResult target = test::run_hilight({"target", "workplane", kRoom, "-o", (dir / "c.csv").string()});
  check_one_line_error(target);
  CHECK_THAT(target.err, Contains("c.csv: unknown output type '.csv'"));
  const test::RunResult exported = test::run_hilight({"export", kRoom, "--lights", kRoomLights, "-o", (dir / "s.obj").string()});
  check_one_line_error(exported);
  CHECK_THAT(exported.err, Contains("s.obj: unknown output type '.obj'"));
  CHECK(!fs::exists(text));
  CHECK(fs::is_empty(dir));
}

TEST_CASE("Lights file: its intensity unit is written and read by it, whatever --units says", "[lights][units]") {
  const fs::path dir = test::output_dir("lights_intensity_unit");
  Lighting lights{Light::point(Vec3(1.f, 2.f, 3.f), Rgb(0.5f, 1.f, 2.f))};
  // Written in the unit asked, stated in the file.
  write_lights_file(dir / "cd.json", lights, Units::Photometric);
  write_lights_file(dir / "wsr.json", lights, Units::Radiometric);
  const auto cd = nlohmann::json::parse(test::read_file(dir / "cd.json"));
  CHECK(cd["intensity_unit"] == "cd");
  CHECK(cd["lights"][0]["intensity"][1].get<double>() == Approx(683.0));
  CHECK(nlohmann::json::parse(test::read_file(dir / "wsr.json"))["intensity_unit"] == "W/sr");
  // Read by the file's own word, whatever the flag.
  for (Units flag : {Units::Radiometric, Units::Photometric}) {
    for (const char* name : {"cd.json", "wsr.json"}) {
      INFO(name);
      const Lighting back = read_lights_file(dir / name, flag);
      REQUIRE(back.size() == 1);
      CHECK(back[0].intensity.g == Approx(1.0f));
    }
  }
  // A file that states nothing (written before the field) is read as the flag says.
  test::write_text(dir / "old.json", R"({"lights":[{"type":"point","position":[0,1,0],"intensity":[683,683,683]}]})");
  CHECK(read_lights_file(dir / "old.json", Units::Photometric)[0].intensity.r == Approx(1.0f));
  CHECK(read_lights_file(dir / "old.json", Units::Radiometric)[0].intensity.r == Approx(683.0f));
  // Any other unit is refused, naming the file.
  test::write_text(dir / "lm.json", R"({"intensity_unit":"lm","lights":[{"type":"point","position":[0,1,0],"intensity":[1,1,1]}]})");
  CHECK_THROWS_WITH(read_lights_file(dir / "lm.json"), Contains("lm.json") && Contains("\"intensity_unit\" must be \"W/sr\" or \"cd\""));
}

TEST_CASE("Lights file: a render of a file in candela is the render of the same lights in W/sr, without --units", "[lights][units][cli]") {
  const fs::path dir = test::output_dir("lights_intensity_unit_cli");
  const Lighting lights = read_lights_file(kRoomLights);
  write_lights_file(dir / "cd.json", lights, Units::Photometric);
  for (const char* name : {"wsr", "cd"}) {
    const std::string in = name == std::string("cd") ? (dir / "cd.json").string() : kRoomLights;
    const test::RunResult r = test::run_hilight({"render", kRoom, "--lights", in, "-o", (dir / (std::string(name) + ".ply")).string(),
                                                 "--bounces", "0"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
  }
  const auto a = test::ply_colours(dir / "wsr.ply"), b = test::ply_colours(dir / "cd.ply");
  REQUIRE(a.size() == b.size());
  CHECK(test::dbar(b, a) < 1e-5);
  // And a solve's lights say what they are in.
  const auto written = nlohmann::json::parse(test::read_file(dir / "cd.json"));
  CHECK(written["intensity_unit"] == "cd");
}
