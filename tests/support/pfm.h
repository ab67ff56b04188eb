#pragma once
// Reads a Portable Float Map (PFM): "PF" (RGB), width height, scale (negative: little-endian),
// then float rows stored BOTTOM to top. Returned with row 0 at the top, like every HDR_Image.
#include "hdr_image.h"

#include <string>

HDR_Image read_pfm(const std::string& path);
