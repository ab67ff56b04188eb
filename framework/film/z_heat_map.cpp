#include "z_heat_map.h"

#include <cmath>

namespace {
// The pixel's most significant channel: the largest |z|, NaN first.
float most_significant(const Spectrum& z) {
	float worst = 0.0f;
	for (int ch = 0; ch < 3; ch++) {
		if (std::isnan(z[ch])) return z[ch];
		if (std::abs(z[ch]) > std::abs(worst)) worst = z[ch];
	}
	return worst;
}

Srgb8 mix(const Srgb8& a, const Srgb8& b, double t) {
	Srgb8 c{};
	for (int i = 0; i < 3; i++) c[i] = uint8_t(std::lround(a[i] + t * (b[i] - a[i])));
	return c;
}

// The inverse of the sRGB curve that write_png applies (IEC 61966-2-1).
float srgb_decode(uint8_t value) {
	float v = float(value) / 255.0f;
	if (v <= 0.04045f) return v / 12.92f;
	return std::pow((v + 0.055f) / 1.055f, 2.4f);
}
} // namespace

Srgb8 z_colour(float z, double z_critical) {
	using namespace z_colours;
	if (std::isnan(z)) return not_a_number;
	if (std::abs(z) > z_critical) return z > 0 ? fail_too_bright : fail_too_dark;
	return mix(zero, z > 0 ? noise_too_bright : noise_too_dark, std::abs(z) / z_critical);
}

std::vector<Srgb8> z_colours_of(const HDR_Image& z, double z_critical) {
	std::vector<Srgb8> colours(z.pixels.size());
	for (size_t i = 0; i < z.pixels.size(); i++) colours[i] = z_colour(most_significant(z.pixels[i]), z_critical);
	return colours;
}

HDR_Image z_heat_map(const HDR_Image& z, double z_critical) {
	HDR_Image map(z.w, z.h);
	std::vector<Srgb8> colours = z_colours_of(z, z_critical);
	for (size_t i = 0; i < colours.size(); i++) {
		const Srgb8& colour = colours[i];
		map.pixels[i] = Spectrum(srgb_decode(colour[0]), srgb_decode(colour[1]), srgb_decode(colour[2]));
	}
	return map;
}
