#pragma once
// Image files. PNG is for looking at (exposure, then the sRGB curve, 8 bits); EXR holds linear
// float data (renders, variances, references). Reading accepts .exr and Radiance .hdr.
// Writing is all or nothing (output_file.h): a failed write leaves no file and keeps the old one.
// All functions throw Input_Error with the file name on failure.
#include "hdr_image.h"

#include <array>
#include <cstdint>
#include <string>

// A linear colour as a PNG's pixel at exposure 0: 8-bit sRGB (./lab view's samples layer).
std::array<uint8_t, 3> png_pixel(Spectrum linear);

// exposure in stops: each channel is multiplied by 2^exposure before the sRGB curve.
void write_png(const std::string& path, const HDR_Image& image, float exposure = 0.0f);
void write_exr(const std::string& path, const HDR_Image& image);
HDR_Image read_image(const std::string& path); // .exr or .hdr, by extension
