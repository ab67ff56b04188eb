// A reference split over machines (./lab references --pass P/N, then --merge): the passes, merged
// from their film files, are the stored reference rendered whole, up to the order of the sums
// (framework/film/film_file.h). Checked on eye_bunny, the cheapest graded scene, in three passes.
#include "film_file.h"
#include "graded_images.h"
#include "image_io.h"
#include "temp_dir.h"

#include "lab_catch2.h"

#include <cmath>

TEST_CASE("a reference rendered in three passes and merged is the stored reference", "[images]") {
	Graded_Scene graded = graded_scene("eye_bunny"); // (a copy: GCC 14 suspects a reference to a temporary)
	Scene scene = load_graded(graded);
	uint32_t samples = scene.settings.samples * REFERENCE_SPP_FACTOR;
	Temp_Dir dir;
	std::vector<std::string> files;
	for (uint32_t pass = 1; pass <= 3; pass++) {
		Render_Options options;
		options.pass = pass, options.passes = 3;
		files.push_back(dir.file("pass" + std::to_string(pass) + ".exr"));
		write_film(files.back(), render_graded(graded, scene, samples, REFERENCE_SEED, options),
		           Film_Origin{graded.name, REFERENCE_SEED, samples, pass, 3});
	}
	HDR_Image merged = merge_films(files).film.mean();
	HDR_Image stored = read_image(reference_file(graded.name, "_mean.exr"));
	REQUIRE(merged.w == stored.w);
	REQUIRE(merged.h == stored.h);
	// Both are doubles rounded to floats; the doubles differ by far less than a float's unit (the
	// bound of tests/framework/test_film_passes.cpp), so the floats differ by at most one unit.
	size_t differ = 0;
	for (size_t i = 0; i < merged.pixels.size(); i++) {
		for (int c = 0; c < 3; c++) {
			float a = merged.pixels[i][c], b = stored.pixels[i][c];
			if (a != b && std::nextafter(a, b) != b) differ++;
		}
	}
	INFO(differ << " pixel channels differ by more than one float unit from "
	            << reference_file(graded.name, "_mean.exr"));
	CHECK(differ == 0);
}
