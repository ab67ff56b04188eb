#include "pfm.h"

#include <cstring>
#include <fstream>
#include <stdexcept>

HDR_Image read_pfm(const std::string& path) {
	std::ifstream file(path, std::ios::binary);
	std::string magic;
	uint32_t w = 0, h = 0;
	float scale = 0.0f;
	if (!(file >> magic >> w >> h >> scale) || magic != "PF" || w == 0 || h == 0) {
		throw std::runtime_error(path + ": not an RGB PFM file");
	}
	if (scale > 0.0f) throw std::runtime_error(path + ": big-endian PFM is not supported");
	file.get(); // the single whitespace character after the header
	HDR_Image image(w, h);
	for (uint32_t row = 0; row < h; row++) {
		uint32_t y = h - 1 - row;
		if (!file.read(reinterpret_cast<char*>(&image.at(0, y)), std::streamsize(sizeof(float) * 3 * w))) {
			throw std::runtime_error(path + ": truncated PFM data");
		}
	}
	return image;
}
