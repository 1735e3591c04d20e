#pragma once
// The HTML report's lux grids (io/html_report.hpp): each grid's points seen
// from above as false-colour squares, with Ē, Emin and U0 against what was
// wanted, and the luminaires marked.
#include "hilight/illuminance_criteria.hpp"
#include "hilight/lighting.hpp"
#include "hilight/solve/illuminance_design.hpp"

#include <string>

namespace hilight {

std::string lux_maps_html(const IlluminanceCriteria& criteria, const DesignReport& design, const Lighting& lights);

} // namespace hilight
