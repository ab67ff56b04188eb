#include "film.h"

void Pixel_Stats::add(Spectrum sample) {
	if (!is_finite(sample)) {
		non_finite++;
		return;
	}
	count++;
	glm::dvec3 x(sample);
	glm::dvec3 delta = x - mean;
	mean += delta / double(count);
	m2 += delta * (x - mean);
}

void Pixel_Stats::merge(const Pixel_Stats& other) {
	non_finite += other.non_finite;
	if (other.count == 0) return;
	double n_a = count, n_b = other.count, n = n_a + n_b;
	glm::dvec3 delta = other.mean - mean;
	mean += delta * (n_b / n);
	m2 += other.m2 + delta * delta * (n_a * n_b / n);
	count += other.count;
}

HDR_Image Film::mean() const {
	HDR_Image image(w, h);
	for (size_t i = 0; i < pixels.size(); i++) image.pixels[i] = pixels[i].mean_value();
	return image;
}

HDR_Image Film::variance() const {
	HDR_Image image(w, h);
	for (size_t i = 0; i < pixels.size(); i++) image.pixels[i] = pixels[i].variance_value();
	return image;
}

uint64_t Film::non_finite() const {
	uint64_t total = 0;
	for (const Pixel_Stats& p : pixels) total += p.non_finite;
	return total;
}

HDR_Image Film::non_finite_map() const {
	HDR_Image image(w, h);
	for (size_t i = 0; i < pixels.size(); i++) image.pixels[i] = Spectrum(pixels[i].non_finite > 0 ? 1.0f : 0.0f);
	return image;
}
