#include "sample_rate_map.h"
#include "heat_ramp.h"

#include <algorithm>

HDR_Image sample_rate_map(const Film& film, uint32_t max_samples) {
	HDR_Image map(film.w, film.h);
	for (size_t i = 0; i < film.pixels.size(); i++) {
		const Pixel_Stats& pixel = film.pixels[i];
		map.pixels[i] = heat_ramp(float(pixel.count + pixel.non_finite) / float(std::max(1u, max_samples)));
	}
	return map;
}
