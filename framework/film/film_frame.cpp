#include "film_frame.h"
#include "film.h"

Film_Frame::Film_Frame(uint32_t width, uint32_t height)
	: estimate{HDR_Image(width, height), HDR_Image(width, height), {}, std::vector<uint32_t>(size_t(width) * height)},
	  non_finite(size_t(width) * height) {
}

Film_Frame Film_Frame::from(const Film& film, uint32_t samples, double seconds) {
	Film_Frame frame(film.w, film.h);
	frame.samples = samples;
	frame.seconds = seconds;
	for (size_t i = 0; i < film.pixels.size(); i++) frame.set_pixel(i, film);
	return frame;
}

void Film_Frame::set_pixel(size_t i, const Film& film) {
	const Pixel_Stats& pixel = film.pixels[i];
	estimate.mean.pixels[i] = pixel.mean_value();
	estimate.variance.pixels[i] = pixel.variance_value();
	estimate.samples[i] = pixel.count;
	non_finite[i] = pixel.non_finite;
}

uint64_t Film_Frame::non_finite_total() const {
	uint64_t total = 0;
	for (uint32_t n : non_finite) total += n;
	return total;
}
