#pragma once
// The HTML report's plans (io/html_report.hpp): each storey cut 1.5 m over
// its floor and seen from above (plan_view.hpp) — the target and the result
// at one exposure, walls cut through in grey — with each light standing in
// that storey marked by its number and the lux on the surface below it.
#include "hilight/io/html_report.hpp"

#include <string>

namespace hilight {

std::string plans_html(const HtmlReport& page, int width);

} // namespace hilight
