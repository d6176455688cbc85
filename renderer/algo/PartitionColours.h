// The partition overlay's colours (shared_constants.h: SL_PARTITION_COLOUR_*, the same table
// composite.frag uses): the one C++ copy, for the outside view's light frusta and the
// Partitions panel's captions.
#pragma once

#include <glm/vec3.hpp>

namespace sl {

/// The overlay colour of map `map` (linear 0..1 RGB): SL_PARTITION_COLOUR_<map mod
/// SL_PARTITION_COLOURS>, negative indices wrapped the same way.
glm::vec3 partitionColour(int map);

}  // namespace sl
