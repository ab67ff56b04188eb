#include "image_io.h"
#include "error.h"
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

void create_parent_directory(const std::string& path) {
	fs::path parent = fs::path(path).parent_path();
	if (parent.empty()) return;
	std::error_code error;
	fs::create_directories(parent, error);
	if (error) throw Input_Error(path + ": cannot create directory " + parent.string() + ": " + error.message());
}

// Checks what every writer needs: a non-empty image (stb and tinyexr fail badly on 0 x h) and the
// directory to put it in.
void prepare_to_write(const std::string& path, const HDR_Image& image) {
	if (image.w == 0 || image.h == 0) {
		throw Input_Error(path + ": cannot write an empty image (" + std::to_string(image.w) + " x " +
		                  std::to_string(image.h) + " pixels)");
	}
	create_parent_directory(path);
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

// tinyexr reports errors through a string it allocates.
std::string take_exr_message(const char* message) {
	std::string text = message ? message : "unknown error";
	if (message) FreeEXRErrorMessage(message);
	return text;
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

} // namespace

void write_png(const std::string& path, const HDR_Image& image, float exposure) {
	prepare_to_write(path, image);
	float scale = std::exp2(exposure);
	std::vector<uint8_t> bytes;
	bytes.reserve(image.pixels.size() * 3);
	for (const Spectrum& pixel : image.pixels) {
		for (int c = 0; c < 3; c++) bytes.push_back(png_channel(pixel[c], scale));
	}
	int stride = int(image.w) * 3;
	if (!stbi_write_png(path.c_str(), int(image.w), int(image.h), 3, bytes.data(), stride)) {
		throw Input_Error(path + ": cannot write PNG image");
	}
}

void write_exr(const std::string& path, const HDR_Image& image) {
	prepare_to_write(path, image);
	const char* message = nullptr;
	static_assert(sizeof(Spectrum) == 3 * sizeof(float), "HDR_Image pixels must be packed RGB floats");
	const float* rgb = reinterpret_cast<const float*>(image.pixels.data());
	// 3 components, stored as 32-bit floats (save_as_fp16 = 0): linear data, no loss.
	if (SaveEXR(rgb, int(image.w), int(image.h), 3, 0, path.c_str(), &message) != TINYEXR_SUCCESS) {
		throw Input_Error(path + ": cannot write EXR image: " + take_exr_message(message));
	}
}

HDR_Image read_image(const std::string& path) {
	if (!std::ifstream(path)) throw Input_Error(path + ": cannot open the file (does it exist?)");
	std::string ext = lowercase_extension(path);
	if (ext == ".exr") return read_exr(path);
	if (ext == ".hdr") return decode_radiance_hdr(path, read_text_file(path));
	throw Input_Error(path + ": unsupported image format '" + ext + "' (expected .exr or .hdr)");
}
