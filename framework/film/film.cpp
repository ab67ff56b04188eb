#include "film.h"

void Pixel_Stats::add(Spectrum sample) {
	if (!is_finite(sample)) {
		non_finite++;
		return;
	}
	count++;
	glm::dvec3 x(sample);
	glm::dvec3 delta = x - mean;
	// m4 and m3 first: their updates use m2 and m3 before this sample (Pébay 2008, eq. 2.1-2.3).
	double n = count;
	glm::dvec3 delta_n = delta / n, term = delta * delta_n * (n - 1.0);
	m4 += term * delta_n * delta_n * (n * n - 3.0 * n + 3.0) + 6.0 * delta_n * delta_n * m2 - 4.0 * delta_n * m3;
	m3 += term * delta_n * (n - 2.0) - 3.0 * delta_n * m2;
	mean += delta / double(count);
	m2 += delta * (x - mean);
}

void Pixel_Stats::merge(const Pixel_Stats& other) {
	non_finite += other.non_finite;
	if (other.count == 0) return;
	double n_a = count, n_b = other.count, n = n_a + n_b;
	glm::dvec3 delta = other.mean - mean, delta2 = delta * delta;
	// m4 and m3 first: they use this side's m2 and m3 as they were (Pébay 2008, eq. 3.1).
	m4 += other.m4 + delta2 * delta2 * (n_a * n_b * (n_a * n_a - n_a * n_b + n_b * n_b) / (n * n * n)) +
	      6.0 * delta2 * (n_a * n_a * other.m2 + n_b * n_b * m2) / (n * n) +
	      4.0 * delta * (n_a * other.m3 - n_b * m3) / n;
	m3 += other.m3 + delta2 * delta * (n_a * n_b * (n_a - n_b) / (n * n)) + 3.0 * delta * (n_a * other.m2 - n_b * m2) / n;
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

HDR_Image Film::fourth_moment() const {
	HDR_Image image(w, h);
	for (size_t i = 0; i < pixels.size(); i++) {
		const Pixel_Stats& p = pixels[i];
		image.pixels[i] = p.count > 1 ? Spectrum(p.m4 / double(p.count)) : Spectrum{0.0f};
	}
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
