#include "film_stream.h"
#include "error.h"
#include "film.h"

#include <cstring>
#include <istream>
#include <ostream>

namespace {
constexpr char MAGIC[4] = {'L', 'A', 'B', 'F'};

struct Header {
	char magic[4];
	uint32_t version, width, height, samples;
	double seconds;
};

struct Pixel_Record {
	float mean[3], variance[3];
	uint32_t count, non_finite;
};

void read_exactly(std::istream& in, void* data, size_t size, const char* what) {
	in.read(static_cast<char*>(data), std::streamsize(size));
	if (size_t(in.gcount()) != size) {
		throw Input_Error(std::string("film stream: the stream ended inside a frame's ") + what);
	}
}
} // namespace

uint64_t Film_Frame::non_finite_total() const {
	uint64_t total = 0;
	for (uint32_t n : non_finite) total += n;
	return total;
}

void write_frame(std::ostream& out, const Film& film, uint32_t samples, double seconds) {
	Header header{};
	std::memcpy(header.magic, MAGIC, sizeof MAGIC);
	header.version = FILM_STREAM_VERSION;
	header.width = film.w;
	header.height = film.h;
	header.samples = samples;
	header.seconds = seconds;
	out.write(reinterpret_cast<const char*>(&header), sizeof header);
	// The same values as Image_Estimate::from(film), which the graders compare.
	std::vector<Pixel_Record> records(film.pixels.size());
	for (size_t i = 0; i < records.size(); i++) {
		const Pixel_Stats& pixel = film.pixels[i];
		Spectrum mean = pixel.mean_value(), variance = pixel.variance_value();
		records[i] = {{mean.r, mean.g, mean.b}, {variance.r, variance.g, variance.b}, pixel.count, pixel.non_finite};
	}
	out.write(reinterpret_cast<const char*>(records.data()), std::streamsize(records.size() * sizeof(Pixel_Record)));
	out.flush();
}

bool read_frame(std::istream& in, Film_Frame& frame) {
	Header header{};
	if (in.peek() == std::char_traits<char>::eof()) return false;
	read_exactly(in, &header, sizeof header, "header");
	if (std::memcmp(header.magic, MAGIC, sizeof MAGIC) != 0) {
		throw Input_Error("film stream: a frame must start with \"LABF\" (is this a renderer started with --stream?)");
	}
	if (header.version != FILM_STREAM_VERSION) {
		throw Input_Error("film stream: version " + std::to_string(header.version) + ", expected " +
		                  std::to_string(FILM_STREAM_VERSION) + " (renderer and viewer of different builds?)");
	}
	uint64_t pixels = uint64_t(header.width) * header.height;
	if (pixels == 0 || pixels > FILM_STREAM_MAX_PIXELS) {
		throw Input_Error("film stream: a frame of " + std::to_string(header.width) + " x " +
		                  std::to_string(header.height) + " pixels (expected 1 to 4096 x 4096)");
	}
	std::vector<Pixel_Record> records(pixels);
	read_exactly(in, records.data(), records.size() * sizeof(Pixel_Record), "pixels");
	frame.samples = header.samples;
	frame.seconds = header.seconds;
	frame.estimate.mean = HDR_Image(header.width, header.height);
	frame.estimate.variance = HDR_Image(header.width, header.height);
	frame.estimate.samples.resize(pixels);
	frame.non_finite.resize(pixels);
	for (size_t i = 0; i < pixels; i++) {
		frame.estimate.mean.pixels[i] = Spectrum(records[i].mean[0], records[i].mean[1], records[i].mean[2]);
		frame.estimate.variance.pixels[i] =
			Spectrum(records[i].variance[0], records[i].variance[1], records[i].variance[2]);
		frame.estimate.samples[i] = records[i].count;
		frame.non_finite[i] = records[i].non_finite;
	}
	return true;
}
