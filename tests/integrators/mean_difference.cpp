// Whether two renders estimate the same image, by their means over all pixels, channel by channel:
// a z-test of each difference, each mean's variance the sum of its pixels' s^2 / spp over the square
// of their count (the pixels are independent; a pixel's channels are not, hence a test each).
// Exit status 0 if every |z| is within the critical value of three two-sided tests at alpha = 1e-6
// together (Bonferroni: 1e-6 / 3 each, 5.10), 1 if not, 2 for bad input.
//   mean_difference A.exr A_VARIANCE.exr B.exr B_VARIANCE.exr SPP
#include "error.h"
#include "image_io.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace {
struct Image_Mean {
	double mean[3] = {}, variance[3] = {}; // of each channel's mean
};

Image_Mean image_mean(const std::string& mean_file, const std::string& variance_file, double spp) {
	HDR_Image mean = read_image(mean_file), variance = read_image(variance_file);
	if (mean.w != variance.w || mean.h != variance.h) throw Input_Error(variance_file + ": not the size of " + mean_file);
	double pixels = double(mean.pixels.size());
	Image_Mean result;
	for (size_t i = 0; i < mean.pixels.size(); i++) {
		for (int c = 0; c < 3; c++) {
			result.mean[c] += mean.pixels[i][c] / pixels;
			result.variance[c] += variance.pixels[i][c] / spp / (pixels * pixels);
		}
	}
	return result;
}
} // namespace

int main(int argc, char** argv) {
	constexpr double Z_CRITICAL = 5.10; // two-sided, alpha = 1e-6 / 3
	if (argc != 6) {
		std::fprintf(stderr, "usage: mean_difference A.exr A_VARIANCE.exr B.exr B_VARIANCE.exr SPP\n");
		return 2;
	}
	try {
		double spp = std::stod(argv[5]);
		Image_Mean a = image_mean(argv[1], argv[2], spp), b = image_mean(argv[3], argv[4], spp);
		bool same = true;
		for (int c = 0; c < 3; c++) {
			double z = (a.mean[c] - b.mean[c]) / std::sqrt(a.variance[c] + b.variance[c]);
			std::printf("channel %d: image means %.6f and %.6f, z = %.2f (critical %.2f)\n", c, a.mean[c], b.mean[c], z,
			            Z_CRITICAL);
			same = same && std::abs(z) <= Z_CRITICAL;
		}
		return same ? 0 : 1;
	} catch (const std::exception& e) {
		std::fprintf(stderr, "mean_difference: %s\n", e.what());
		return 2;
	}
}
