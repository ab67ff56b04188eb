#include "image_io.h"
#include "error.h"
#include "exr_encoding.h"
#include "output_file.h"
#include "radiance_hdr.h"
#include "text_file.h"

// The Debian packages ship compiled implementations of stb and tinyexr: include declarations only.
#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The sRGB transfer function (IEC 61966-2-1): linear below 0.0031308, a 1/2.4 power above.
float srgb_encode(float linear) {
	if (linear <= 0.0031308f) return 12.92f * linear;
	return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// One 8-bit PNG channel: exposure, sRGB curve, clamp to [0, 1], round. NaN becomes 0.
uint8_t png_channel(float linear, float scale) {
	float value = srgb_encode(linear * scale);
	if (!(value > 0.0f)) return 0;
	return uint8_t(std::lround(std::min(value, 1.0f) * 255.0f));
}

// stb and tinyexr fail badly on an image of 0 x h pixels.
void require_pixels(const std::string& path, const HDR_Image& image) {
	if (image.w == 0 || image.h == 0) {
		throw Input_Error(path + ": cannot write an empty image (" + std::to_string(image.w) + " x " +
		                  std::to_string(image.h) + " pixels)");
	}
}

std::string lowercase_extension(const std::string& path) {
	std::string ext = fs::path(path).extension().string();
	std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	return ext;
}

// Copies `channels` floats per pixel (the first three are RGB) into an image.
HDR_Image image_from_floats(const float* data, int w, int h, int channels) {
	HDR_Image image{uint32_t(w), uint32_t(h)};
	for (size_t i = 0; i < image.pixels.size(); i++) {
		const float* p = data + i * size_t(channels);
		image.pixels[i] = Spectrum(p[0], p[1], p[2]);
	}
	return image;
}

HDR_Image read_exr(const std::string& path) {
	float* rgba = nullptr;
	int w = 0, h = 0;
	const char* message = nullptr;
	if (LoadEXR(&rgba, &w, &h, path.c_str(), &message) != TINYEXR_SUCCESS) {
		throw Input_Error(path + ": cannot read EXR image: " + take_exr_message(message));
	}
	HDR_Image image = image_from_floats(rgba, w, h, 4);
	std::free(rgba);
	return image;
}

// The image as the bytes of an OpenEXR file: 32-bit float channels B, G, R (the order most viewers
// expect), uncompressed below 16 x 16 pixels and ZIP-compressed above, as tinyexr's SaveEXR writes.
std::string encode_exr(const std::string& path, const HDR_Image& image) {
	std::vector<Exr_Channel> channels{{"B", {}, {}}, {"G", {}, {}}, {"R", {}, {}}};
	for (int c = 0; c < 3; c++) {
		for (const Spectrum& pixel : image.pixels) channels[c].floats.push_back(pixel[2 - c]);
	}
	bool small = image.w < 16 && image.h < 16;
	return encode_exr(path, "the EXR image", image.w, image.h, channels,
	                  small ? Exr_Compression::none : Exr_Compression::zip);
}

} // namespace

std::array<uint8_t, 3> png_pixel(Spectrum linear) {
	return {png_channel(linear.r, 1.0f), png_channel(linear.g, 1.0f), png_channel(linear.b, 1.0f)};
}

void write_png(const std::string& path, const HDR_Image& image, float exposure) {
	require_pixels(path, image);
	float scale = std::exp2(exposure);
	std::vector<uint8_t> rgb;
	rgb.reserve(image.pixels.size() * 3);
	for (const Spectrum& pixel : image.pixels) {
		for (int c = 0; c < 3; c++) rgb.push_back(png_channel(pixel[c], scale));
	}
	std::string bytes;
	auto append = [](void* to, void* data, int size) {
		static_cast<std::string*>(to)->append(static_cast<char*>(data), size_t(size));
	};
	int stride = int(image.w) * 3;
	if (!stbi_write_png_to_func(append, &bytes, int(image.w), int(image.h), 3, rgb.data(), stride)) {
		throw Input_Error(path + ": cannot encode the PNG image");
	}
	write_file(path, bytes);
}

void write_exr(const std::string& path, const HDR_Image& image) {
	require_pixels(path, image);
	write_file(path, encode_exr(path, image));
}

HDR_Image read_image(const std::string& path) {
	if (!std::ifstream(path)) throw Input_Error(path + ": cannot open the file (does it exist?)");
	std::string ext = lowercase_extension(path);
	if (ext == ".exr") return read_exr(path);
	if (ext == ".hdr") return decode_radiance_hdr(path, read_text_file(path));
	throw Input_Error(path + ": unsupported image format '" + ext + "' (expected .exr or .hdr)");
}
