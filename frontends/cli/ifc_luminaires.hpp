#pragma once
/// The luminaires of a solve written into a copy of its input IFC (issue
/// 34 §6), through Debian's IfcPlusPlus (libifcplusplus-dev): each an
/// IfcLightFixture with its outline as a thin box, placed in the IfcSpace
/// whose extruded footprint holds it (else the storey below it) and
/// referenced there (IfcRelReferencedInSpatialStructure: assimp crashes on
/// a contained IFC4 element), its photometry, dimming, flux and power in a
/// property set. IfcPlusPlus reads IFC2X3 and IFC4 and writes IFC4 (IfcLightFixture
/// is IFC4's), so the copy is IFC4. docs/interchange.md, "IFC".
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace hilight::cli {

struct IfcLuminaire {
  glm::dvec3 position{0.0};  ///< hilight's world (the scene file's axes, +Y up), metres
  glm::dvec3 aim{0.0, -1.0, 0.0};
  double spin_deg = 0;  ///< C0's turn about the aim from +X
  glm::dvec2 size{0.0};  ///< length along C0, width across, metres (0: a point)
  std::string product, profile;
  double dimming = 1, flux_lm = 0, power_w = 0;
};

struct IfcWritten {
  size_t in_spaces = 0, in_storeys = 0;
  std::vector<std::string> spaces;  ///< per luminaire, the IfcSpace's name (or the storey's)
};

/// True when this build can write IFC (IfcPlusPlus was found).
bool ifc_output_available();

/// Reads `source` (an IFC the scene was loaded from), adds the luminaires,
/// writes `out` atomically. InputError naming the file when it cannot be
/// read as IFC or this build has no IfcPlusPlus.
IfcWritten write_ifc_luminaires(const std::filesystem::path& source, const std::filesystem::path& out,
                                const std::vector<IfcLuminaire>& luminaires);

/// The IfcLightFixture entities of an IFC file, read back with IfcPlusPlus
/// (for the tests and `hilight info`): name, world position (hilight's
/// axes, metres) and the name of the spatial element containing it.
struct IfcFixture {
  std::string name, container;
  glm::dvec3 position{0.0};
};
std::vector<IfcFixture> read_ifc_fixtures(const std::filesystem::path& file);

} // namespace hilight::cli
