// Hostile: answers the judge itself, on the answer channel (descriptor 4), with @LENGTH@ bytes whose
// first eight say that a list of as many rays follows: a judge that allocated the rays a count
// asks for before reading them would take about 40 bytes of memory for each byte received.
#include "camera.h"
#include "pathtracer.h"

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace {
[[noreturn]] void answer_with_a_huge_count(uint32_t kind) {
	const uint32_t magic = 0x4a4c5450, sequence = 1, status = 0;
	const uint64_t length = @LENGTH@, count = length - 8;
	char header[4 * 4 + 8 + 8];
	std::memcpy(header, &magic, 4);
	std::memcpy(header + 4, &kind, 4);
	std::memcpy(header + 8, &sequence, 4);
	std::memcpy(header + 12, &status, 4);
	std::memcpy(header + 16, &length, 8);
	std::memcpy(header + 24, &count, 8);
	(void)!write(4, header, sizeof header);
	std::vector<char> zeros(size_t(1) << 20, 0);
	for (uint64_t sent = 8; sent < length;) {
		ssize_t n = write(4, zeros.data(), size_t(std::min<uint64_t>(zeros.size(), length - sent)));
		if (n <= 0) break;
		sent += uint64_t(n);
	}
	_exit(0);
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	answer_with_a_huge_count(1); // generate_rays
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	answer_with_a_huge_count(2); // trace_pixels
}
