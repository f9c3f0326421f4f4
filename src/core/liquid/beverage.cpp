#include "core/liquid/beverage.hpp"

namespace draught {

glm::vec3 srm_to_absorption(float srm) {
  return srm * glm::vec3(kAbsorptionPerSrm[0], kAbsorptionPerSrm[1], kAbsorptionPerSrm[2]);
}

glm::vec3 liquid_absorption(const LiquidParams& l) { return l.srm > 0 ? srm_to_absorption(l.srm) : l.absorption; }

}  // namespace draught
