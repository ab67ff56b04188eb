// The film stream (framework/film/film_stream.h): what a renderer started with --stream writes after
// each batch of samples, and ./lab view reads.
#include "film.h"
#include "film_stream.h"
#include "error.h"

#include "lab_catch2.h"

#include <sstream>

namespace {
Film small_film() {
	Film film(3, 2);
	for (size_t i = 0; i < film.pixels.size(); i++) {
		for (int s = 0; s <= int(i); s++) film.pixels[i].add(Spectrum(0.1f * float(s), float(i), 2.0f + float(s)));
	}
	film.pixels[4].add(Spectrum(NAN, 0.0f, 0.0f));
	return film;
}
} // namespace

TEST_CASE("A film frame reads back as the film's estimate the graders compare, frame after frame", "[film_stream]") {
	Film film = small_film();
	Image_Estimate written = Image_Estimate::from(film); // what the graders compare
	std::stringstream pipe;
	write_frame(pipe, Film_Frame::from(film, 6, 0.25));
	write_frame(pipe, Film_Frame::from(film, 6, 0.25));
	Film_Frame read;
	for (int frame = 0; frame < 2; frame++) {
		REQUIRE(read_frame(pipe, read));
		CHECK(read.samples == 6);
		CHECK(read.seconds == 0.25);
		CHECK(read.width() == 3);
		CHECK(read.height() == 2);
		CHECK(read.estimate.samples == written.samples);
		CHECK(read.non_finite == std::vector<uint32_t>{0, 0, 0, 0, 1, 0});
		CHECK(read.non_finite_total() == 1);
		for (size_t i = 0; i < 6; i++) {
			CHECK(read.estimate.mean.pixels[i] == written.mean.pixels[i]);
			CHECK(read.estimate.variance.pixels[i] == written.variance.pixels[i]);
		}
	}
	CHECK_FALSE(read_frame(pipe, read)); // the end of the stream, between frames
}

TEST_CASE("A film stream cut inside a frame, or that is not one, is an error that says so", "[film_stream]") {
	std::stringstream pipe;
	write_frame(pipe, Film_Frame::from(small_film(), 6, 0.25));
	std::string bytes = pipe.str();
	std::stringstream cut(bytes.substr(0, bytes.size() - 5));
	Film_Frame frame;
	CHECK_THROWS_WITH(read_frame(cut, frame), contains_text("ended inside a frame's non-finite counts"));
	std::stringstream text("loaded scenes/cornell_box.json in 0.01 s\n........................................");
	CHECK_THROWS_WITH(read_frame(text, frame), contains_text("must start with \"LABF\""));
}
