#pragma once
// A picture of where a render differs from its reference (the grade report's heat map, the live
// viewer's z-map): per pixel,
// the channel with the largest |z| (image_compare.h) on a diverging colour scale,
//
//     |z| <= z_critical:  white (z = 0) fading to pale red (z > 0: too bright) or pale blue (z < 0:
//                         too dark) at |z| = z_critical: noise;
//     |z| >  z_critical:  saturated dark red or dark blue: the pixel fails its test;
//     z NaN:              black (the render's mean is not a number).
//
// So a correct render is a pale, speckled image, and a wrong one shows its mistakes in dark colour.
#include "hdr_image.h"

#include <array>
#include <cstdint>
#include <vector>

using Srgb8 = std::array<uint8_t, 3>;

// The scale's colours, for the report's legend.
namespace z_colours {
constexpr Srgb8 zero{255, 255, 255};
constexpr Srgb8 noise_too_bright{244, 165, 130}; // at z = +z_critical
constexpr Srgb8 noise_too_dark{146, 197, 222};   // at z = -z_critical
constexpr Srgb8 fail_too_bright{178, 24, 43};
constexpr Srgb8 fail_too_dark{33, 102, 172};
constexpr Srgb8 not_a_number{0, 0, 0};
} // namespace z_colours

// The colour of one pixel's z.
Srgb8 z_colour(float z, double z_critical);

// The colours of a z image (z_scores), pixel by pixel: what the page of ./lab view shows.
std::vector<Srgb8> z_colours_of(const HDR_Image& z, double z_critical);

// The heat map of a z image (z_scores), in linear values that write_png turns back into exactly
// these sRGB colours (write it with exposure 0).
HDR_Image z_heat_map(const HDR_Image& z, double z_critical);
