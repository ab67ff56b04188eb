#pragma once
// Radiance .hdr images (Greg Ward's RGBE format), decoded by the framework itself: a header that
// starts with "#?" and ends with an empty line, the resolution line "-Y height +X width" (rows
// from the top, pixels from the left), then one scanline per row, each either flat (4 bytes a
// pixel: R, G, B mantissas and a shared exponent E) or run-length encoded per channel. A pixel is
// (R, G, B) * 2^(E - 136), or black if E = 0.
//
// Every malformed or truncated file is an Input_Error naming the file and what is wrong, e.g.
// "scanline 412 of 512 is cut off". (Debian 12's stb_image loops forever on a truncated
// run-length-encoded file and fills a truncated flat one with black rows.)
#include "hdr_image.h"

#include <string>

// `bytes` is the whole content of the file `path` (named in errors).
HDR_Image decode_radiance_hdr(const std::string& path, const std::string& bytes);
