// Image files (framework/film/image_io.h): EXR keeps linear floats exactly, PNG applies exposure and the
// sRGB curve, .hdr files can be read, and every failure names the file.
#include "error.h"
#include "image_io.h"
#include "output_file.h"
#include "temp_dir.h"

#include "lab_catch2.h"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include <sys/resource.h>

namespace {

// Every pixel different, every channel different: a flipped, transposed or channel-swapped image
// cannot pass for the original.
HDR_Image distinct_pixels(uint32_t w, uint32_t h) {
	HDR_Image image(w, h);
	for (uint32_t y = 0; y < h; y++) {
		for (uint32_t x = 0; x < w; x++) {
			float i = float(y * w + x);
			image.at(x, y) = Spectrum(i + 0.125f, -0.5f * i - 0.25f, 1.0f / (i + 3.0f));
		}
	}
	return image;
}

// The 8-bit RGB values of a PNG file, read back with stb_image.
std::vector<uint8_t> read_png(const std::string& path, int expected_w, int expected_h) {
	int w = 0, h = 0, channels = 0;
	uint8_t* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
	REQUIRE(data != nullptr);
	REQUIRE(w == expected_w);
	REQUIRE(h == expected_h);
	std::vector<uint8_t> bytes(data, data + size_t(w) * h * 3);
	stbi_image_free(data);
	return bytes;
}

// The red channel of a one-row PNG written from the given linear values.
std::vector<int> png_values(const Temp_Dir& dir, const std::vector<float>& linear, float exposure) {
	HDR_Image image(uint32_t(linear.size()), 1);
	for (size_t i = 0; i < linear.size(); i++) image.pixels[i] = Spectrum(linear[i], 0.0f, 1.0f);
	std::string path = dir.file("row.png");
	write_png(path, image, exposure);
	std::vector<uint8_t> bytes = read_png(path, int(linear.size()), 1);
	std::vector<int> red;
	for (size_t i = 0; i < linear.size(); i++) red.push_back(bytes[3 * i]);
	return red;
}

bool same_bits(float a, float b) {
	return std::memcmp(&a, &b, sizeof(float)) == 0;
}

// An image that no encoder can compress much: each channel a hash of its index.
HDR_Image noise(uint32_t w, uint32_t h) {
	HDR_Image image(w, h);
	uint32_t state = 12345;
	for (Spectrum& pixel : image.pixels) {
		for (int c = 0; c < 3; c++) {
			state = state * 1664525u + 1013904223u; // a linear congruential generator (Numerical Recipes)
			pixel[c] = float(state >> 8) / float(1u << 24);
		}
	}
	return image;
}

std::string file_bytes(const std::string& path) {
	std::ifstream in(path, std::ios::binary);
	return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> files_in(const Temp_Dir& dir) {
	std::vector<std::string> names;
	for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.path())) {
		names.push_back(std::filesystem::relative(entry.path(), dir.path()).string());
	}
	std::sort(names.begin(), names.end());
	return names;
}

// While it lives, no file of this process may grow beyond `bytes`: a write past it fails with
// EFBIG ("File too large"), as a full disk fails with ENOSPC.
class File_Size_Limit {
public:
	explicit File_Size_Limit(rlim_t bytes) {
		getrlimit(RLIMIT_FSIZE, &previous);
		previous_handler = std::signal(SIGXFSZ, SIG_IGN); // else the kernel ends the process
		rlimit limit = previous;
		limit.rlim_cur = bytes;
		REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
	}
	~File_Size_Limit() {
		setrlimit(RLIMIT_FSIZE, &previous);
		std::signal(SIGXFSZ, previous_handler);
	}

private:
	rlimit previous{};
	void (*previous_handler)(int) = nullptr;
};

} // namespace

TEST_CASE("write_exr then read_image gives back the same floats, bit for bit, rows top to bottom") {
	Temp_Dir dir;
	HDR_Image image = distinct_pixels(5, 3);
	// Values a 16-bit EXR would round or overflow: float32 storage must keep them all.
	image.at(0, 0) = Spectrum(1e-30f, 0.1f, 1e6f);
	image.at(4, 2) = Spectrum(-3.5f, 65504.0f * 8.0f, 0.0f);
	std::string path = dir.file("image.exr");
	write_exr(path, image);

	HDR_Image back = read_image(path);
	REQUIRE(back.w == image.w);
	REQUIRE(back.h == image.h);
	for (uint32_t y = 0; y < image.h; y++) {
		for (uint32_t x = 0; x < image.w; x++) {
			for (int c = 0; c < 3; c++) {
				CAPTURE(x, y, c, image.at(x, y)[c], back.at(x, y)[c]);
				CHECK(same_bits(back.at(x, y)[c], image.at(x, y)[c]));
			}
		}
	}
}

TEST_CASE("write_png applies the sRGB curve (IEC 61966-2-1), clamps and rounds to 8 bits") {
	Temp_Dir dir;
	// Expected 8-bit codes of the standard piecewise sRGB curve, round(255 * srgb(x)):
	//   0 -> 0; 0.001 -> 3 and 0.0031308 -> 10 (linear segment 12.92 x); 0.2 -> 124; 0.5 -> 188;
	//   1 -> 255; anything above 1 clamps to 255 and anything below 0 to 0.
	// A plain gamma 2.2 curve would give 11, 19, 123, 186 instead.
	std::vector<float> linear{0.0f, 0.001f, 0.0031308f, 0.2f, 0.5f, 1.0f, 4.0f, -1.0f};
	std::vector<int> expected{0, 3, 10, 124, 188, 255, 255, 0};
	CHECK(png_values(dir, linear, 0.0f) == expected);
}

TEST_CASE("write_png exposure is in stops: +1 doubles the linear value, -1 halves it") {
	Temp_Dir dir;
	// 0.25 * 2 and 1 / 2 are both linear 0.5, which is sRGB code 188.
	CHECK(png_values(dir, {0.25f}, 1.0f) == std::vector<int>{188});
	CHECK(png_values(dir, {1.0f}, -1.0f) == std::vector<int>{188});
}

TEST_CASE("write_png keeps the channels and the row order") {
	Temp_Dir dir;
	HDR_Image image(2, 2);
	image.at(0, 0) = Spectrum(1, 0, 0); // top-left red
	image.at(1, 0) = Spectrum(0, 1, 0); // top-right green
	image.at(0, 1) = Spectrum(0, 0, 1); // bottom-left blue
	image.at(1, 1) = Spectrum(1, 1, 1); // bottom-right white
	std::string path = dir.file("quad.png");
	write_png(path, image);
	std::vector<uint8_t> bytes = read_png(path, 2, 2);
	std::vector<uint8_t> expected{255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
	CHECK(bytes == expected);
}

TEST_CASE("writing an image creates the missing parent directories") {
	Temp_Dir dir;
	HDR_Image image(2, 1, Spectrum(0.5f));
	std::string png = dir.file("a/b/image.png");
	std::string exr = dir.file("c/d/image.exr");
	write_png(png, image);
	write_exr(exr, image);
	CHECK(std::filesystem::exists(png));
	CHECK(std::filesystem::exists(exr));
}

TEST_CASE("read_image reads Radiance .hdr files, rows top to bottom") {
	Temp_Dir dir;
	// RGBE stores one shared 8-bit exponent and an 8-bit mantissa per channel, so a channel is exact
	// only to 2^-8 of the pixel's largest channel (2^-7 after rounding the exponent up).
	const int w = 3, h = 2;
	std::vector<float> rgb{1.0f, 0.5f, 0.25f, 4.0f, 2.0f, 1.0f, 0.1f, 0.2f, 0.3f,
	                       0.0f, 0.0f, 0.0f, 8.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.75f};
	std::string path = dir.file("sky.hdr");
	REQUIRE(stbi_write_hdr(path.c_str(), w, h, 3, rgb.data()));

	HDR_Image image = read_image(path);
	REQUIRE(image.w == uint32_t(w));
	REQUIRE(image.h == uint32_t(h));
	for (size_t i = 0; i < image.pixels.size(); i++) {
		float largest = std::max({rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
		for (int c = 0; c < 3; c++) {
			CAPTURE(i, c, rgb[3 * i + c], image.pixels[i][c]);
			CHECK(image.pixels[i][c] == Approx(rgb[3 * i + c]).margin(largest / 128.0f));
		}
	}
}

TEST_CASE("reading a missing, corrupt or unsupported image throws Input_Error naming the file") {
	Temp_Dir dir;
	std::string missing = dir.file("missing.exr");
	std::string corrupt = dir.file("corrupt.exr");
	std::string corrupt_hdr = dir.file("corrupt.hdr");
	std::string png = dir.file("picture.png");
	std::ofstream(corrupt) << "this is not an OpenEXR file";
	std::ofstream(corrupt_hdr) << "this is not a Radiance file";
	write_png(png, HDR_Image(1, 1));

	for (const std::string& path : {missing, corrupt, corrupt_hdr, png}) {
		CAPTURE(path);
		CHECK_THROWS_AS(read_image(path), Input_Error);
		CHECK_THROWS_WITH(read_image(path), contains_text(path));
	}
	CHECK_THROWS_WITH(read_image(png), contains_text(".exr") && contains_text(".hdr"));
}

TEST_CASE("writing where no file can be created throws Input_Error naming the file") {
	Temp_Dir dir;
	std::string blocker = dir.file("not_a_directory");
	std::ofstream(blocker) << "a file where a directory is needed";
	std::string png = blocker + "/image.png";
	std::string exr = blocker + "/image.exr";
	CHECK_THROWS_AS(write_png(png, HDR_Image(1, 1)), Input_Error);
	CHECK_THROWS_WITH(write_png(png, HDR_Image(1, 1)), contains_text(png));
	CHECK_THROWS_WITH(write_exr(exr, HDR_Image(1, 1)), contains_text(exr));
}

TEST_CASE("writing an empty image (width or height 0) throws Input_Error naming the file") {
	Temp_Dir dir;
	std::string png = dir.file("empty.png");
	std::string exr = dir.file("empty.exr");
	CHECK_THROWS_WITH(write_png(png, HDR_Image(0, 4)), contains_text(png));
	CHECK_THROWS_WITH(write_exr(exr, HDR_Image(3, 0)), contains_text(exr));
	CHECK_FALSE(std::filesystem::exists(png));
	CHECK_FALSE(std::filesystem::exists(exr));
}

TEST_CASE("writing an image to a full device fails with the system's reason; the device stays a device") {
	Temp_Dir dir;
	std::string full_png = dir.file("full.png"), full_exr = dir.file("full.exr");
	std::filesystem::create_symlink("/dev/full", full_png);
	std::filesystem::create_symlink("/dev/full", full_exr);
	std::string reason = std::strerror(ENOSPC); // "No space left on device"
	CHECK_THROWS_WITH(write_png(full_png, noise(8, 8)), contains_text(full_png) && contains_text(reason));
	CHECK_THROWS_WITH(write_exr(full_exr, noise(8, 8)), contains_text(full_exr) && contains_text(reason));
	CHECK(std::filesystem::is_symlink(full_png));
	CHECK(std::filesystem::is_character_file("/dev/full"));
}

TEST_CASE("an image write cut short leaves no file behind and keeps the file it was to replace") {
	Temp_Dir dir;
	std::string png = dir.file("image.png"), exr = dir.file("image.exr");
	write_png(png, HDR_Image(2, 2, Spectrum(0.5f)));
	write_exr(exr, HDR_Image(2, 2, Spectrum(0.5f)));
	std::string old_png = file_bytes(png), old_exr = file_bytes(exr);
	std::vector<std::string> before = files_in(dir);
	std::string reason = std::strerror(EFBIG);
	HDR_Image large = noise(256, 256); // about 200 kB as PNG and as EXR, even compressed
	{
		File_Size_Limit limit(64 * 1024);
		CHECK_THROWS_WITH(write_png(png, large), contains_text(png) && contains_text(reason));
		CHECK_THROWS_WITH(write_exr(exr, large), contains_text(exr) && contains_text(reason));
		CHECK_THROWS_WITH(write_png(dir.file("new/image.png"), large), contains_text(reason));
	}
	CHECK(file_bytes(png) == old_png);
	CHECK(file_bytes(exr) == old_exr);
	CHECK(files_in(dir) == before); // no temporary file, no new file or folder
}

TEST_CASE("check_writable fails for a path that cannot be written, and leaves nothing behind") {
	Temp_Dir dir;
	std::ofstream(dir.file("blocker")) << "a file where a directory is needed";
	std::filesystem::create_directory(dir.file("folder.png"));
	std::vector<std::string> before = files_in(dir);
	check_writable(dir.file("fine.png"));
	check_writable(dir.file("a/b/c/fine.png")); // folders it would create
	CHECK_THROWS_WITH(check_writable(dir.file("blocker/image.png")),
	                  contains_text("blocker/image.png") && contains_text(std::strerror(ENOTDIR)));
	CHECK_THROWS_WITH(check_writable(dir.file("folder.png")), contains_text("folder.png: is a folder"));
	CHECK_THROWS_WITH(check_writable("/proc/image.exr"), contains_text("/proc/image.exr"));
	CHECK(files_in(dir) == before);
}
