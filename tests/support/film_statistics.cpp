#include "film_statistics.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

Film_Mean film_mean(const Film& film, int channel, const std::function<bool(uint32_t, uint32_t)>& select) {
	Film_Mean result;
	double sum = 0.0, variance_sum = 0.0;
	for (uint32_t y = 0; y < film.h; y++) {
		for (uint32_t x = 0; x < film.w; x++) {
			if (!select(x, y)) continue;
			const Pixel_Stats& p = film.pixels[size_t(y) * film.w + x];
			sum += p.mean[channel];
			// Variance of this pixel's mean: s^2 / n with s^2 = m2 / (n - 1).
			if (p.count > 1) variance_sum += p.m2[channel] / double(p.count - 1) / double(p.count);
			result.pixels++;
			result.samples += p.count;
		}
	}
	if (result.pixels == 0) return result;
	double n = double(result.pixels);
	result.mean = sum / n;
	result.standard_error = std::sqrt(variance_sum) / n;
	return result;
}

Mean_Check compare_mean(const Film& film, int channel, double expected, double z_critical, const std::string& what,
                        const std::function<bool(uint32_t, uint32_t)>& select) {
	Film_Mean m = film_mean(film, channel, select);
	// The selected pixel farthest from the expected value, to point at in the message.
	double worst = -1.0, worst_value = 0.0;
	uint32_t worst_x = 0, worst_y = 0;
	for (uint32_t y = 0; y < film.h; y++) {
		for (uint32_t x = 0; x < film.w; x++) {
			if (!select(x, y)) continue;
			double v = film.pixels[size_t(y) * film.w + x].mean[channel];
			if (std::abs(v - expected) <= worst) continue;
			worst = std::abs(v - expected), worst_x = x, worst_y = y, worst_value = v;
		}
	}
	double allowed = z_critical * m.standard_error + FLOAT_SLACK * std::max(1.0, std::abs(expected));
	Mean_Check check;
	check.pass = m.pixels > 0 && m.samples > 0 && std::abs(m.mean - expected) <= allowed;
	std::ostringstream s;
	s.precision(7);
	s << what << ": measured " << m.mean << ", expected " << expected << " (allowed difference " << allowed
	  << " = " << z_critical << " standard errors of " << m.standard_error << " + float rounding); " << m.pixels
	  << " pixels, " << m.samples << " samples";
	if (m.pixels > 0) {
		s << "; the pixel farthest from " << expected << " is (" << worst_x << ", " << worst_y << ") = " << worst_value;
	}
	if (m.pixels == 0) s << " [no pixel selected: the test itself is wrong]";
	check.message = s.str();
	return check;
}

const char* channel_name(int channel) {
	constexpr const char* names[3] = {"red", "green", "blue"};
	return names[channel];
}

void check_mean(const Film& film, int channel, double expected, double z_critical, const std::string& what,
                const std::function<bool(uint32_t, uint32_t)>& select) {
	Mean_Check check =
		compare_mean(film, channel, expected, z_critical, what + ", " + channel_name(channel) + " channel", select);
	INFO(check.message);
	CHECK(check.pass);
}

bool check_mean_rgb(const Film& film, glm::dvec3 expected, double z_critical, const std::string& what,
                    const std::function<bool(uint32_t, uint32_t)>& select, const std::string& if_too_dark) {
	std::string failures;
	bool all_too_dark = true, channels_alike = true;
	double first_measured = film_mean(film, 0, select).mean;
	for (int c = 0; c < 3; c++) {
		Film_Mean m = film_mean(film, c, select);
		channels_alike = channels_alike && m.mean == first_measured && expected[c] == expected[0];
		Mean_Check check = compare_mean(film, c, expected[c], z_critical, std::string(channel_name(c)) + " channel", select);
		if (check.pass) continue;
		all_too_dark = all_too_dark && m.mean < expected[c];
		failures += (failures.empty() ? "" : "; ") + check.message;
	}
	bool pass = failures.empty();
	if (!pass && channels_alike) {
		failures = compare_mean(film, 0, expected[0], z_critical, "every channel", select).message;
	}
	INFO(what << ": " << failures << (all_too_dark && !if_too_dark.empty() ? ". " + if_too_dark : ""));
	CHECK(pass);
	return pass;
}
