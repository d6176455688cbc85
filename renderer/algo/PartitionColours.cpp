// The partition overlay's colour table (PartitionColours.h), read from shared_constants.h.
#include "PartitionColours.h"

#include "common/shared_constants.h"

namespace sl {

glm::vec3 partitionColour(int map) {
  static const float table[SL_PARTITION_COLOURS][3] = {
      {SL_PARTITION_COLOUR_0}, {SL_PARTITION_COLOUR_1}, {SL_PARTITION_COLOUR_2},
      {SL_PARTITION_COLOUR_3}, {SL_PARTITION_COLOUR_4}, {SL_PARTITION_COLOUR_5},
      {SL_PARTITION_COLOUR_6}, {SL_PARTITION_COLOUR_7}};
  const int i = ((map % SL_PARTITION_COLOURS) + SL_PARTITION_COLOURS) % SL_PARTITION_COLOURS;
  return {table[i][0], table[i][1], table[i][2]};
}

}  // namespace sl
