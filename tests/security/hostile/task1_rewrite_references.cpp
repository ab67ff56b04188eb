// Hostile: before main(), overwrites the graded scene's reference image (and its checksum file) with
// a black image, so that its black render would match; the task code is the stub.
#include "camera.h"
#include "hdr_image.h"
#include "pathtracer.h"

#include <fstream>
#include <string>

// The framework's image I/O is not in the student's API; declared by hand, it is linked all the same.
void write_exr(const std::string& path, const HDR_Image& image);

namespace {
int rewrite() {
	for (const char* root : {"@ROOT@", ".", ".."}) {
		std::string references = std::string(root) + "/scenes/graded/references/";
		try {
			write_exr(references + "eye_bunny_mean.exr", HDR_Image(64, 64));
			write_exr(references + "eye_bunny_var.exr", HDR_Image(64, 64));
		} catch (...) {
		}
		std::ofstream(references + "SHA256SUMS", std::ios::app) << "forged\n";
	}
	return 0;
}
int rewritten = rewrite();
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	return Ray{}; // the stub
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	return Spectrum{0.0f};
}
