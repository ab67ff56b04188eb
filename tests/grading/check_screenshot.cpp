// check_screenshot FILE.png MIN_COLOURS RRGGBB...: checks that a browser's screenshot is a real
// render of a page: it has at least MIN_COLOURS distinct colours (a blank or failed page has a few)
// and each listed colour covers at least MIN_PIXELS pixels (e.g. a badge's background, a colour of
// an embedded image: present only if the CSS applied and the image decoded).
#include <stb/stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

namespace {
constexpr long MIN_PIXELS = 100;

long count_pixels(const unsigned char* rgb, long pixels, unsigned long colour) {
	long count = 0;
	for (long i = 0; i < pixels; i++) {
		const unsigned char* p = rgb + 3 * i;
		count += (unsigned long)(p[0] << 16 | p[1] << 8 | p[2]) == colour;
	}
	return count;
}
} // namespace

int main(int argc, char** argv) {
	if (argc < 3) {
		std::fprintf(stderr, "usage: check_screenshot FILE.png MIN_COLOURS [RRGGBB...]\n");
		return 2;
	}
	int w = 0, h = 0, channels = 0;
	unsigned char* rgb = stbi_load(argv[1], &w, &h, &channels, 3);
	if (!rgb) {
		std::fprintf(stderr, "check_screenshot: %s is not a readable PNG: %s\n", argv[1], stbi_failure_reason());
		return 1;
	}
	long pixels = long(w) * h;
	std::set<unsigned long> colours;
	for (long i = 0; i < pixels; i++) colours.insert(rgb[3 * i] << 16 | rgb[3 * i + 1] << 8 | rgb[3 * i + 2]);
	int failures = 0;
	long min_colours = std::atol(argv[2]);
	std::printf("check_screenshot: %s is %d x %d with %zu distinct colours\n", argv[1], w, h, colours.size());
	if (long(colours.size()) < min_colours) {
		std::fprintf(stderr, "check_screenshot: only %zu colours (at least %ld expected): a blank page?\n",
		             colours.size(), min_colours);
		failures++;
	}
	for (int a = 3; a < argc; a++) {
		long count = count_pixels(rgb, pixels, std::strtoul(argv[a], nullptr, 16));
		std::printf("check_screenshot: #%s covers %ld pixels\n", argv[a], count);
		if (count < MIN_PIXELS) {
			std::fprintf(stderr, "check_screenshot: #%s covers %ld pixels, expected at least %ld\n", argv[a], count,
			             MIN_PIXELS);
			failures++;
		}
	}
	stbi_image_free(rgb);
	return failures == 0 ? 0 : 1;
}
