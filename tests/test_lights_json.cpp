// The lights file: round trip and every malformed input named precisely.
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

TEST_CASE("lights survive a write/read round trip", "[lights]") {
  Lighting lights = {Light::point({1.f, 2.f, 3.f}, Rgb(0.5f, 1.f, 2.f)),
                     Light::spot({0.f, 3.f, 0.f}, {0.f, -2.f, 0.f}, 30.f, Rgb(4.f), 5.f)};
  auto dir = test::output_dir("lights_roundtrip");
  write_lights_json(dir / "l.json", lights);
  Lighting back = read_lights_json(dir / "l.json");
  REQUIRE(back.size() == 2);
  CHECK(back[0].type == LightType::Point);
  CHECK(back[0].position == lights[0].position);
  CHECK(back[0].intensity == lights[0].intensity);
  CHECK(back[1].type == LightType::Spot);
  CHECK(back[1].direction == Vec3(0.f, -1.f, 0.f));  // normalized on input
  CHECK(back[1].cutoff_deg == 30.f);
  CHECK(back[1].falloff_deg == 5.f);
}

TEST_CASE("malformed lights files are refused with the file, light and problem named", "[lights][bad-input]") {
  auto bad = [](const std::string& text) { return parse_lights_json(text, "L.json"); };
  CHECK_THROWS_WITH(bad("{\"lights\": ["), Catch::StartsWith("L.json: malformed JSON"));
  CHECK_THROWS_WITH(bad("{\"lights\": 3}"), Catch::Contains("\"lights\" array"));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"intensity":[1,1,1]}]})"), Catch::Contains("light 0: missing \"position\""));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"position":[0,0,0],"intensity":[1,-1,1]}]})"), Catch::Contains("negative intensity"));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"position":[0,0],"intensity":[1,1,1]}]})"), Catch::Contains("array of 3 numbers"));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"type":"spot","position":[0,0,0],"direction":[0,0,0],"cutoff_deg":20,"intensity":[1,1,1]}]})"),
                    Catch::Contains("zero-length spot direction"));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"type":"spot","position":[0,0,0],"direction":[0,1,0],"intensity":[1,1,1]}]})"),
                    Catch::Contains("cutoff_deg"));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"type":"area","position":[0,0,0],"intensity":[1,1,1]}]})"), Catch::Contains("unknown light type"));
  CHECK_THROWS_WITH(bad(R"({"lights":[{"position":[0,0,0],"intensity":[1,1,1],"colour":1}]})"), Catch::Contains("unknown field \"colour\""));
  CHECK_THROWS_WITH(bad(R"({"lights":[{},{"position":[0,0,0]}]})"), Catch::Contains("light 0"));
  CHECK_THROWS_WITH(read_lights_json("/no/such/lights.json"), Catch::Contains("/no/such/lights.json"));
}
