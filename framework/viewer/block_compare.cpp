#include "block_compare.h"
#include "significance.h"

#include <algorithm>
#include <cmath>
#include <sstream>

Block_Comparison compare_blocks(const Image_Estimate& student, const Image_Estimate& reference, uint32_t block,
                                double alpha) {
	Block_Comparison c;
	uint32_t w = student.mean.w, h = student.mean.h;
	uint32_t blocks_x = (w + block - 1) / block, blocks_y = (h + block - 1) / block;
	c.tests = size_t(blocks_x) * blocks_y * 3;
	c.block = block, c.blocks_x = blocks_x;
	c.block_z.assign(size_t(blocks_x) * blocks_y, 0.0);
	c.z_critical = stats::two_sided_z(stats::sidak(alpha, c.tests));
	for (uint32_t by = 0; by < blocks_y; by++) {
		for (uint32_t bx = 0; bx < blocks_x; bx++) {
			uint32_t x0 = bx * block, y0 = by * block, x1 = std::min(w, x0 + block) - 1, y1 = std::min(h, y0 + block) - 1;
			for (int ch = 0; ch < 3; ch++) {
				// The difference of the two blocks' pixel means summed, and its variance.
				double difference = 0.0, variance = 0.0, size = 0.0;
				bool sampled = true;
				for (uint32_t y = y0; y <= y1; y++) {
					for (uint32_t x = x0; x <= x1; x++) {
						size_t i = size_t(y) * w + x;
						double n_s = student.samples[i], n_r = reference.samples[i];
						sampled = sampled && n_s >= 1.0 && n_r >= 1.0;
						double m_s = student.mean.pixels[i][ch], m_r = reference.mean.pixels[i][ch];
						double v_r = reference.variance.pixels[i][ch];
						double v_s = std::max(double(student.variance.pixels[i][ch]), v_r);
						difference += m_s - m_r;
						variance += v_s / std::max(n_s, 1.0) + v_r / std::max(n_r, 1.0);
						size += std::abs(m_s) + std::abs(m_r);
					}
				}
				if (!sampled) continue; // a pixel without samples yet: the per-pixel test reports it
				// Float rounding of the means: a relative floor, as the per-pixel test's (image_compare.h).
				double floor = IMAGE_SIGMA_FLOOR * 0.5 * size;
				double z = difference == 0.0 ? 0.0 : difference / std::sqrt(variance + floor * floor);
				double& block_z = c.block_z[size_t(by) * blocks_x + bx];
				if (!(std::abs(z) <= std::abs(block_z))) block_z = z;
				if (!(std::abs(z) <= std::abs(c.worst_z))) {
					c.worst_z = z;
					c.worst_x0 = x0, c.worst_y0 = y0, c.worst_x1 = x1, c.worst_y1 = y1;
				}
			}
		}
	}
	c.pass = std::abs(c.worst_z) <= c.z_critical;
	std::ostringstream out;
	out.precision(3);
	out << "the means over blocks of " << block << " x " << block << " pixels " << (c.pass ? "agree" : "differ")
	    << " (worst: pixels " << c.worst_x0 << "-" << c.worst_x1 << " x " << c.worst_y0 << "-" << c.worst_y1
	    << ", z = " << c.worst_z;
	if (!c.pass) out << ", the render is too " << (c.worst_z < 0.0 ? "dark" : "bright") << " there";
	out << "; allowed |z| <= " << c.z_critical << ")";
	c.message = out.str();
	return c;
}

void mark_failing_blocks(const Block_Comparison& blocks, uint32_t width, uint32_t height, std::vector<Srgb8>& colours) {
	for (size_t b = 0; b < blocks.block_z.size(); b++) {
		double z = blocks.block_z[b];
		if (!(std::abs(z) > blocks.z_critical)) continue;
		Srgb8 fail = z < 0.0 ? z_colours::fail_too_dark : z_colours::fail_too_bright;
		uint32_t x0 = uint32_t(b % blocks.blocks_x) * blocks.block, y0 = uint32_t(b / blocks.blocks_x) * blocks.block;
		for (uint32_t y = y0; y < std::min(height, y0 + blocks.block); y++) {
			for (uint32_t x = x0; x < std::min(width, x0 + blocks.block); x++) {
				Srgb8& colour = colours[size_t(y) * width + x];
				bool already = colour == z_colours::fail_too_dark || colour == z_colours::fail_too_bright ||
				               colour == z_colours::not_a_number;
				if (!already) colour = fail;
			}
		}
	}
}
