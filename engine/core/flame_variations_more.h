// Variations of JWildfire, Fractorium and Apophysis plugins that real flame files use, kept apart
// from flame_variations.cpp's catalogue so that each file stays readable. Internal to the
// catalogue: buildCatalogue() appends these entries to its own.
#pragma once

#include <vector>

#include "flame_variations.h"

namespace voxflame::core {

void addMoreVariations(std::vector<VariationInfo>& catalogue);

}  // namespace voxflame::core
