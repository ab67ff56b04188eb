#include "radiance_hdr.h"
#include "error.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace {

// Run-length-encoded scanlines are between these widths; others are always flat.
constexpr uint32_t MIN_RLE_WIDTH = 8, MAX_RLE_WIDTH = 0x7fff;

// The file's bytes, read front to back; every error names the file and, in the pixels, the scanline.
class Reader {
public:
	Reader(const std::string& path, const std::string& bytes) : path(path), bytes(bytes) {
	}

	[[noreturn]] void fail(const std::string& what) const {
		throw Input_Error(path + ": " + what);
	}
	[[noreturn]] void fail_scanline(const std::string& what) const {
		fail("scanline " + std::to_string(row + 1) + " of " + std::to_string(height) + " " + what);
	}

	// The next line without its '\n'; false at the end of the file.
	bool line(std::string& text) {
		size_t end = bytes.find('\n', next);
		if (end == std::string::npos) return false;
		text = bytes.substr(next, end - next);
		next = end + 1;
		return true;
	}

	// Whether the next bytes start a run-length-encoded scanline: 2, 2, and a width below 2^15.
	bool starts_rle_scanline() const {
		return bytes.size() - next >= 4 && bytes[next] == 2 && bytes[next + 1] == 2 && !(uint8_t(bytes[next + 2]) & 0x80);
	}

	uint8_t byte() {
		if (next == bytes.size()) cut_off();
		return uint8_t(bytes[next++]);
	}
	void need(size_t count) const {
		if (bytes.size() - next < count) cut_off();
	}

	uint32_t row = 0, height = 0; // the scanline being read, for messages

private:
	[[noreturn]] void cut_off() const {
		fail_scanline("is cut off (the file ends after " + std::to_string(bytes.size()) + " bytes)");
	}

	const std::string& path;
	const std::string& bytes;
	size_t next = 0;
};

// "#?RADIANCE" (or another program's name after "#?"), variables such as FORMAT=, comments, and an
// empty line.
void read_header(Reader& in) {
	std::string line;
	if (!in.line(line) || line.rfind("#?", 0) != 0) {
		in.fail("not a Radiance HDR file (expected a first line \"#?RADIANCE\")");
	}
	for (;;) {
		if (!in.line(line)) in.fail("the header does not end (expected an empty line, then \"-Y height +X width\")");
		if (line.empty()) return;
		if (line.rfind("FORMAT=", 0) != 0) continue;
		std::string format = line.substr(7, line.find_last_not_of(" \t\r") - 6);
		if (format != "32-bit_rle_rgbe") in.fail("unsupported FORMAT=" + format + " (expected FORMAT=32-bit_rle_rgbe)");
	}
}

// A width or height from 1 to 65535 (far beyond any environment map), or 0 if the text is not one.
uint32_t dimension(const std::string& text) {
	uint32_t value = 0;
	auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
	return status == std::errc() && end == text.data() + text.size() && value <= 65535 ? value : 0;
}

// "-Y height +X width": the only orientation the lab reads (rows from the top, pixels from the left).
void read_resolution(Reader& in, uint32_t& width, uint32_t& height) {
	std::string line, minus_y, plus_x, h, w, rest;
	bool found = in.line(line);
	std::istringstream(line) >> minus_y >> h >> plus_x >> w >> rest;
	width = dimension(w);
	height = dimension(h);
	if (!found || minus_y != "-Y" || plus_x != "+X" || !rest.empty() || width == 0 || height == 0) {
		in.fail("unsupported resolution line \"" + line +
		        "\" (expected \"-Y height +X width\", each from 1 to 65535, e.g. -Y 512 +X 1024)");
	}
}

// Four bytes a pixel. (1, 1, 1, n) marks a run in Radiance's old encoding, which no current writer
// produces and this reader does not decode.
void read_flat_scanline(Reader& in, std::vector<uint8_t>& rgbe) {
	in.need(rgbe.size());
	for (size_t i = 0; i < rgbe.size(); i++) rgbe[i] = in.byte();
	for (size_t x = 0; 4 * x < rgbe.size(); x++) {
		if (rgbe[4 * x] == 1 && rgbe[4 * x + 1] == 1 && rgbe[4 * x + 2] == 1) {
			in.fail_scanline("uses the old run-length encoding (pixel " + std::to_string(x + 1) +
			                 " is a run marker 1 1 1 n), which is not supported: save the image again");
		}
	}
}

// 2, 2, then the width in two bytes; then each channel in turn as packets: a count c > 128 followed
// by one byte repeated c - 128 times, or a count 1 to 128 followed by that many bytes.
void read_rle_scanline(Reader& in, std::vector<uint8_t>& rgbe) {
	const uint32_t width = uint32_t(rgbe.size() / 4);
	in.byte();
	in.byte();
	uint32_t declared = uint32_t(in.byte()) << 8;
	declared |= in.byte();
	if (declared != width) {
		in.fail_scanline("says it is " + std::to_string(declared) + " pixels wide, expected " + std::to_string(width));
	}
	for (int channel = 0; channel < 4; channel++) {
		for (uint32_t x = 0; x < width;) {
			uint8_t code = in.byte();
			bool run = code > 128;
			uint32_t count = run ? code - 128u : code;
			if (count == 0 || x + count > width) {
				in.fail_scanline("is corrupt: a packet of " + std::to_string(count) + " pixels at pixel " +
				                 std::to_string(x + 1) + " does not fit in the width " + std::to_string(width));
			}
			uint8_t value = run ? in.byte() : 0;
			for (uint32_t end = x + count; x < end; x++) rgbe[4 * x + channel] = run ? value : in.byte();
		}
	}
}

// R, G, B mantissas and the shared exponent E: (R, G, B) * 2^(E - 136), black if E = 0.
Spectrum rgbe_to_spectrum(const uint8_t* rgbe) {
	if (rgbe[3] == 0) return Spectrum{0.0f};
	float scale = std::ldexp(1.0f, int(rgbe[3]) - 136);
	return Spectrum(float(rgbe[0]) * scale, float(rgbe[1]) * scale, float(rgbe[2]) * scale);
}

} // namespace

HDR_Image decode_radiance_hdr(const std::string& path, const std::string& bytes) {
	Reader in(path, bytes);
	read_header(in);
	uint32_t width = 0, height = 0;
	read_resolution(in, width, height);
	in.height = height;

	// The pixels grow row by row, so a corrupt size in a short file cannot exhaust memory.
	HDR_Image image;
	image.w = width;
	image.h = height;
	std::vector<uint8_t> rgbe(size_t(width) * 4);
	for (uint32_t y = 0; y < height; y++) {
		in.row = y;
		in.need(4);
		bool rle = width >= MIN_RLE_WIDTH && width <= MAX_RLE_WIDTH && in.starts_rle_scanline();
		if (rle) read_rle_scanline(in, rgbe);
		else read_flat_scanline(in, rgbe);
		for (uint32_t x = 0; x < width; x++) image.pixels.push_back(rgbe_to_spectrum(&rgbe[4 * size_t(x)]));
	}
	return image;
}
