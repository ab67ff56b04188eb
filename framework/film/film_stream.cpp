#include "film_stream.h"
#include "error.h"

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

template <class T>
void write_plane(std::ostream& out, const std::vector<T>& plane) {
	out.write(reinterpret_cast<const char*>(plane.data()), std::streamsize(plane.size() * sizeof(T)));
}

void read_exactly(std::istream& in, void* data, size_t size, const char* what) {
	in.read(static_cast<char*>(data), std::streamsize(size));
	if (size_t(in.gcount()) != size) {
		throw Input_Error(std::string("film stream: the stream ended inside a frame's ") + what);
	}
}

template <class T>
void read_plane(std::istream& in, std::vector<T>& plane, const char* what) {
	read_exactly(in, plane.data(), plane.size() * sizeof(T), what);
}
} // namespace

void write_frame(std::ostream& out, const Film_Frame& frame) {
	Header header{};
	std::memcpy(header.magic, MAGIC, sizeof MAGIC);
	header.version = FILM_STREAM_VERSION;
	header.width = frame.width();
	header.height = frame.height();
	header.samples = frame.samples;
	header.seconds = frame.seconds;
	out.write(reinterpret_cast<const char*>(&header), sizeof header);
	write_plane(out, frame.estimate.mean.pixels);
	write_plane(out, frame.estimate.variance.pixels);
	write_plane(out, frame.estimate.samples);
	write_plane(out, frame.non_finite);
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
	if (frame.width() != header.width || frame.height() != header.height) frame = Film_Frame(header.width, header.height);
	frame.samples = header.samples;
	frame.seconds = header.seconds;
	read_plane(in, frame.estimate.mean.pixels, "means");
	read_plane(in, frame.estimate.variance.pixels, "variances");
	read_plane(in, frame.estimate.samples, "sample counts");
	read_plane(in, frame.non_finite, "non-finite counts");
	return true;
}
