#include "hilight/lighting.hpp"


namespace hilight {

const char* to_string(LightType type) { return type == LightType::Spot ? "spot" : "point"; }

} // namespace hilight
