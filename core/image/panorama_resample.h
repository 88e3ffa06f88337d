#pragma once
// Lower-resolution panoramas for decimation, where every triangle error
// warps three panoramas: color is the box average of each block (linear);
// distance is the block's median sample, never an average, so no pixel
// floats between a foreground and the background behind it.

#include "core/image/image.h"

namespace triwalk {

// factor must divide both width and height.
Panorama downsamplePanorama(const Panorama& panorama, int factor);

}  // namespace triwalk
