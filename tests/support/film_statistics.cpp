#include "film_statistics.h"

#include "lab_catch2.h"

#include <cmath>
#include <sstream>

namespace {
// The reference's per-sample variance of pixel i, channel c: m2 / (N - 1).
double reference_variance(const Film& reference, size_t i, int c) {
	const Pixel_Stats& p = reference.pixels[i];
	return p.count > 1 ? p.m2[c] / double(p.count - 1) : 0.0;
}
} // namespace

Film_Mean film_mean(const Furnace_Render& render, int channel, const Pixel_Selection& select) {
	const Film& film = render.film;
	Film_Mean result;
	double sum = 0.0, variance_sum = 0.0;
	for (uint32_t y = 0; y < film.h; y++) {
		for (uint32_t x = 0; x < film.w; x++) {
			if (!select(x, y)) continue;
			size_t i = size_t(y) * film.w + x;
			sum += film.pixels[i].mean[channel];
			variance_sum += reference_variance(render.reference, i, channel) / double(render.samples);
			result.pixels++;
		}
	}
	if (result.pixels == 0) return result;
	double n = double(result.pixels);
	result.mean = sum / n;
	result.standard_error = std::sqrt(variance_sum) / n;
	return result;
}

Mean_Check compare_mean(const Furnace_Render& render, int channel, double expected, double z_critical,
                        const std::string& what, const Pixel_Selection& select) {
	const Film& film = render.film;
	Film_Mean m = film_mean(render, channel, select);
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
	check.pass = m.pixels > 0 && std::abs(m.mean - expected) <= allowed;
	std::ostringstream s;
	s.precision(7);
	s << what << ": measured " << m.mean << ", expected " << expected << " (allowed difference " << allowed
	  << " = " << z_critical << " standard errors of " << m.standard_error
	  << " (the reference's noise) + float rounding); " << m.pixels << " pixels, " << render.samples
	  << " samples each";
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

void check_mean(const Furnace_Render& render, int channel, double expected, double z_critical, const std::string& what,
                const Pixel_Selection& select) {
	Mean_Check check =
		compare_mean(render, channel, expected, z_critical, what + ", " + channel_name(channel) + " channel", select);
	INFO(check.message);
	CHECK(check.pass);
}

bool check_mean_rgb(const Furnace_Render& render, glm::dvec3 expected, double z_critical, const std::string& what,
                    const Pixel_Selection& select, const std::string& if_too_dark) {
	std::string failures;
	bool all_too_dark = true, channels_alike = true;
	double first_measured = film_mean(render, 0, select).mean;
	for (int c = 0; c < 3; c++) {
		Film_Mean m = film_mean(render, c, select);
		channels_alike = channels_alike && m.mean == first_measured && expected[c] == expected[0];
		Mean_Check check =
			compare_mean(render, c, expected[c], z_critical, std::string(channel_name(c)) + " channel", select);
		if (check.pass) continue;
		all_too_dark = all_too_dark && m.mean < expected[c];
		failures += (failures.empty() ? "" : "; ") + check.message;
	}
	bool pass = failures.empty();
	if (!pass && channels_alike) {
		failures = compare_mean(render, 0, expected[0], z_critical, "every channel", select).message;
	}
	INFO(what << ": " << failures << (all_too_dark && !if_too_dark.empty() ? ". " + if_too_dark : ""));
	CHECK(pass);
	return pass;
}

bool check_like_reference(const Furnace_Render& render, double z_critical, const std::string& what) {
	const Film& film = render.film;
	const double n = double(render.samples);
	std::string first_failure;
	for (uint32_t by = 0; by < PROBE_BLOCKS && first_failure.empty(); by++) {
		for (uint32_t bx = 0; bx < PROBE_BLOCKS && first_failure.empty(); bx++) {
			uint32_t x0 = bx * film.w / PROBE_BLOCKS, x1 = (bx + 1) * film.w / PROBE_BLOCKS;
			uint32_t y0 = by * film.h / PROBE_BLOCKS, y1 = (by + 1) * film.h / PROBE_BLOCKS;
			for (int c = 0; c < 3; c++) {
				double yours = 0.0, reference = 0.0, variance = 0.0;
				for (uint32_t y = y0; y < y1; y++) {
					for (uint32_t x = x0; x < x1; x++) {
						size_t i = size_t(y) * film.w + x;
						yours += film.pixels[i].mean[c];
						reference += render.reference.pixels[i].mean[c];
						variance += 2.0 * reference_variance(render.reference, i, c) / n;
					}
				}
				double pixels = double((x1 - x0) * (y1 - y0));
				yours /= pixels, reference /= pixels;
				double standard_error = std::sqrt(variance) / pixels;
				double allowed = z_critical * standard_error + FLOAT_SLACK * std::max(1.0, std::abs(reference));
				if (std::abs(yours - reference) <= allowed) continue;
				std::ostringstream s;
				s.precision(5);
				s << what << ": in the pixels (" << x0 << ".." << x1 - 1 << ", " << y0 << ".." << y1 - 1 << "), "
				  << channel_name(c) << " channel, your render's mean is " << yours
				  << " and the reference's own render of the same scene has " << reference << " (allowed difference "
				  << allowed << " = " << z_critical << " standard errors of " << standard_error
				  << " + float rounding; " << render.samples << " samples a pixel each)";
				first_failure = s.str();
				break;
			}
		}
	}
	bool pass = first_failure.empty();
	INFO(first_failure);
	CHECK(pass);
	return pass;
}

Paired_Noise compare_noise(const Furnace_Render& render, double alpha) {
	// One pair per pixel: the per-sample variances summed over the channels (pixels are independent,
	// the channels of one pixel are not).
	std::vector<double> submission, reference, rounding;
	for (size_t i = 0; i < render.film.pixels.size(); i++) {
		const Pixel_Stats &p = render.film.pixels[i], &r = render.reference.pixels[i];
		double s = 0.0, v = 0.0, floor = 0.0;
		for (int c = 0; c < 3; c++) {
			s += p.count > 1 ? p.m2[c] / double(p.count - 1) : 0.0;
			v += reference_variance(render.reference, i, c);
			double sd = FLOAT_SLACK * std::max(1.0, std::abs(r.mean[c]));
			floor += sd * sd;
		}
		submission.push_back(s), reference.push_back(v), rounding.push_back(floor);
	}
	return compare_paired_variances(submission, reference, rounding, alpha);
}

bool check_noise(const Furnace_Render& render, double alpha, const std::string& what, const std::string& if_noisy) {
	Paired_Noise check = compare_noise(render, alpha);
	INFO(what << ": too noisy: " << describe(check, "pixel") << ". " << if_noisy);
	CHECK(check.pass);
	return check.pass;
}
