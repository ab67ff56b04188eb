#include "adaptive_sampling.h"
#include "heat_ramp.h"

#include <cmath>

void Luminance_Sums::add(Spectrum sample) {
	if (!std::isfinite(sample.r) || !std::isfinite(sample.g) || !std::isfinite(sample.b)) return;
	double y = double(luminance(sample));
	n++, sum += y, sum_of_squares += y * y;
}

bool pixel_converged(const Luminance_Sums& sums, const Adaptive_Sampling& rule) {
	if (sums.n < rule.min_samples || sums.n < 2) return false;
	double mean = sums.sum / sums.n;
	double variance = std::max(0.0, (sums.sum_of_squares - sums.sum * mean) / (sums.n - 1));
	return 1.96 * std::sqrt(variance / sums.n) <= rule.threshold * mean;
}

HDR_Image sample_rate_map(const Film& film, uint32_t max_samples) {
	HDR_Image map(film.w, film.h);
	for (size_t i = 0; i < film.pixels.size(); i++) {
		const Pixel_Stats& pixel = film.pixels[i];
		map.pixels[i] = heat_ramp(float(pixel.count + pixel.non_finite) / float(std::max(1u, max_samples)));
	}
	return map;
}
