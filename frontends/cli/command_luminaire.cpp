// hilight luminaire FILE.ies|FILE.ldt: what hilight reads from a luminaire's
// photometry file, as one JSON object (flux rated and integrated, peak,
// symmetry, input watts, efficacy): a check before a solve uses it. With
// --ies OUT it also writes the profile as IES LM-63 (a EULUMDAT file for
// tools that read only IES: Blender's add-on gives it to Cycles that way).
#include "cli_common.hpp"
#include "commands.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/photometry_io.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

namespace hilight::cli {

int run_luminaire(const std::vector<std::string>& args) {
  CLI::App app("Read a luminaire's photometry (IES LM-63 or EULUMDAT) and print what hilight makes of it as JSON", "luminaire");
  std::string path, ies;
  app.add_option("file", path, "the .ies or .ldt file")->required();
  app.add_option("--ies", ies, "also write the profile here as IES LM-63-2002 (.ies; type C, every plane)");
  if (auto code = parse_arguments(app, args)) return *code;
  const Photometry p = read_photometry(path);
  if (!ies.empty()) {
    std::string ext = std::filesystem::path(ies).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".ies") throw InputError(ies, "--ies: the output must be an .ies file");
    write_atomically(ies, ies_text(p));
  }
  static const char* symmetry[] = {"none", "rotational", "about C0-C180", "about C90-C270", "quadrants"};
  const double flux = p.flux();
  nlohmann::json j = {{"file", path},
                      {"type", p.type == Photometry::Type::C ? "C" : "B"},
                      {"symmetry", symmetry[int(p.symmetry)]},
                      {"planes", p.horizontal.size()},
                      {"angles", p.vertical.size()},
                      {"peak_cd", p.peak()},
                      {"flux_lm", flux},
                      {"rated_lamp_lm", p.rated_lumens},
                      {"light_output_ratio", p.rated_lumens > 0 ? nlohmann::json(flux / p.rated_lumens) : nlohmann::json(nullptr)},
                      {"input_w", p.input_watts},
                      {"efficacy_lm_per_w", p.input_watts > 0 ? nlohmann::json(flux / p.input_watts) : nlohmann::json(nullptr)}};
  std::printf("%s\n", j.dump(2).c_str());
  return 0;
}

} // namespace hilight::cli
