// Radiance .hdr images (framework/film/radiance_hdr.h): good files decode exactly, and a truncated or
// corrupt file is an error that names the file and what is wrong, at once (never a hang, never
// black rows).
#include "error.h"
#include "image_io.h"
#include "temp_dir.h"

#include "lab_catch2.h"
#include <stb/stb_image.h>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <regex>

namespace {

const char* const SHIPPED_MAPS[] = {"scenes/hdri/potsdamer_platz_1k.hdr", "scenes/hdri/rooitou_park_1k.hdr"};

std::string file_bytes(const std::string& path) {
	std::ifstream in(path, std::ios::binary);
	REQUIRE(in);
	return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
	std::ofstream(path, std::ios::binary) << bytes;
}

std::string header(uint32_t w, uint32_t h) {
	return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
}

// The R, G, B mantissas and exponent E of pixel (x, y) of the test's flat images: every pixel
// different, a black one (E = 0) at (2, 1), never a run marker (R = G = B = 1).
std::array<uint8_t, 4> test_rgbe(uint32_t x, uint32_t y) {
	if (x == 2 && y == 1) return {200, 100, 50, 0};
	return {uint8_t(128 + (5 * x + y) % 128), uint8_t((11 * x + 3 * y) % 256), uint8_t((x + 7 * y) % 256),
	        uint8_t(100 + (x + 3 * y) % 60)};
}

// A flat (not run-length-encoded) file: four bytes a pixel, rows top to bottom.
std::string flat_hdr(uint32_t w, uint32_t h) {
	std::string bytes = header(w, h);
	for (uint32_t y = 0; y < h; y++) {
		for (uint32_t x = 0; x < w; x++) {
			for (uint8_t b : test_rgbe(x, y)) bytes += char(b);
		}
	}
	return bytes;
}

bool same_bits(float a, float b) {
	return std::memcmp(&a, &b, sizeof(float)) == 0;
}

// The Input_Error message of reading `path`, or "" if it reads.
std::string read_error(const std::string& path) {
	try {
		read_image(path);
	} catch (const Input_Error& e) {
		return e.what();
	}
	return "";
}

} // namespace

TEST_CASE("read_image decodes the shipped run-length-encoded .hdr maps exactly as stb_image does") {
	for (const char* path : SHIPPED_MAPS) {
		CAPTURE(path);
		HDR_Image image = read_image(path);
		int w = 0, h = 0, channels = 0;
		float* expected = stbi_loadf(path, &w, &h, &channels, 3);
		REQUIRE(expected != nullptr);
		CHECK(image.w == uint32_t(w));
		CHECK(image.h == uint32_t(h));
		REQUIRE(image.pixels.size() == size_t(w) * size_t(h));
		size_t different = 0;
		for (size_t i = 0; i < image.pixels.size(); i++) {
			for (int c = 0; c < 3; c++) different += !same_bits(image.pixels[i][c], expected[3 * i + c]);
		}
		stbi_image_free(expected);
		CHECK(different == 0);
	}
}

TEST_CASE("read_image decodes flat .hdr scanlines: (R, G, B) * 2^(E - 136), black where E = 0") {
	Temp_Dir dir;
	// Width 16 could be run-length encoded: the reader must tell a flat scanline by its first bytes.
	for (uint32_t w : {3u, 16u}) {
		const uint32_t h = 5;
		std::string path = dir.file("flat" + std::to_string(w) + ".hdr");
		write_bytes(path, flat_hdr(w, h));
		HDR_Image image = read_image(path);
		REQUIRE(image.w == w);
		REQUIRE(image.h == h);
		for (uint32_t y = 0; y < h; y++) {
			for (uint32_t x = 0; x < w; x++) {
				std::array<uint8_t, 4> rgbe = test_rgbe(x, y);
				for (int c = 0; c < 3; c++) {
					double expected = rgbe[3] == 0 ? 0.0 : std::ldexp(double(rgbe[c]), int(rgbe[3]) - 136);
					CAPTURE(w, x, y, c, int(rgbe[c]), int(rgbe[3]));
					CHECK(double(image.at(x, y)[c]) == expected);
				}
			}
		}
	}
}

TEST_CASE("a truncated run-length-encoded .hdr is an error naming the file and the scanline cut off") {
	// Debian 12's stb_image loops forever on these files: this test hangs if the framework uses it.
	Temp_Dir dir;
	std::string bytes = file_bytes(SHIPPED_MAPS[0]);
	const std::string resolution = "-Y 512 +X 1024\n";
	size_t pixels_start = bytes.find(resolution);
	REQUIRE(pixels_start != std::string::npos);
	pixels_start += resolution.size();

	struct Case {
		size_t size;
		std::string message; // a regular expression
	};
	const Case cases[] = {
		{300000, "scanline ([0-9]+) of 512 is cut off \\(the file ends after 300000 bytes\\)"},
		{pixels_start, "scanline 1 of 512 is cut off"},
		{pixels_start + 3, "scanline 1 of 512 is cut off"},
		{bytes.size() - 1, "scanline 512 of 512 is cut off"},
		{40, "the header does not end"},
	};
	for (const Case& c : cases) {
		std::string path = dir.file("cut" + std::to_string(c.size) + ".hdr");
		write_bytes(path, bytes.substr(0, c.size));
		std::string message = read_error(path);
		CAPTURE(c.size, message);
		CHECK(message.rfind(path + ": ", 0) == 0);
		std::smatch match;
		CHECK(std::regex_search(message, match, std::regex(c.message)));
		if (match.size() > 1) { // 300000 of 1540678 bytes: neither the first nor the last scanline
			CHECK(std::stoi(match[1]) > 1);
			CHECK(std::stoi(match[1]) < 512);
		}
	}
}

TEST_CASE("a truncated flat .hdr is an error naming the scanline cut off, not black rows") {
	Temp_Dir dir;
	const uint32_t w = 16, h = 8;
	std::string bytes = flat_hdr(w, h);
	size_t pixels_start = header(w, h).size();
	struct Case {
		size_t size;
		std::string message;
	};
	const Case cases[] = {
		{pixels_start + 4 * w * 3 + 10, "scanline 4 of 8 is cut off"}, // 3 rows and 10 bytes
		{bytes.size() - 1, "scanline 8 of 8 is cut off"},
	};
	for (const Case& c : cases) {
		std::string path = dir.file("flat_cut" + std::to_string(c.size) + ".hdr");
		write_bytes(path, bytes.substr(0, c.size));
		std::string message = read_error(path);
		CAPTURE(c.size, message);
		CHECK(message.rfind(path + ": ", 0) == 0);
		CHECK(message.find(c.message) != std::string::npos);
	}
}

TEST_CASE("a corrupt .hdr is an error saying what is wrong") {
	Temp_Dir dir;
	// A run-length-encoded scanline of width 16 starts 2, 2, 0, 16; then packets per channel.
	std::string rle_start = header(16, 1) + std::string("\x02\x02\x00", 3);
	struct Case {
		std::string name, bytes, message;
	};
	const Case cases[] = {
		{"not_radiance", "P6\n16 1\n255\n", "expected a first line \"#?RADIANCE\""},
		{"xyz", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x80\x80\x80\x80", "unsupported FORMAT=32-bit_rle_xyze"},
		{"flipped", "#?RADIANCE\n\n+Y 1 +X 1\n\x80\x80\x80\x80", "\"+Y 1 +X 1\" (expected \"-Y height +X width\""},
		{"zero_rows", "#?RADIANCE\n\n-Y 0 +X 1\n", "\"-Y 0 +X 1\""},
		{"huge", "#?RADIANCE\n\n-Y 1 +X 99999999999\n", "\"-Y 1 +X 99999999999\""},
		{"width", rle_start + "\x11" + std::string(64, '\x01'), "scanline 1 of 1 says it is 17 pixels wide, expected 16"},
		{"long_run", rle_start + "\x10" + char(128 + 17) + '\x80', "a packet of 17 pixels at pixel 1 does not fit"},
		{"long_copy", rle_start + "\x10" + char(128 + 15) + '\x80' + '\x02', "a packet of 2 pixels at pixel 16"},
		{"empty_packet", rle_start + "\x10" + '\x00', "a packet of 0 pixels at pixel 1"},
		{"old_rle", header(2, 1) + "\x80\x80\x80\x80\x01\x01\x01\x03", "old run-length encoding (pixel 2 is a run marker"},
	};
	for (const Case& c : cases) {
		std::string path = dir.file(c.name + ".hdr");
		write_bytes(path, c.bytes);
		std::string message = read_error(path);
		CAPTURE(c.name, message);
		CHECK(message.rfind(path + ": ", 0) == 0);
		CHECK(message.find(c.message) != std::string::npos);
	}
}
