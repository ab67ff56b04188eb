#pragma once
// A film as a file, so that a render split into passes (--pass I/N, possibly on other machines) can
// be merged exactly (merge_films). An OpenEXR file whose R, G, B channels are the mean (any viewer
// shows the picture), with the rest of each pixel's statistics beside it: the sample counts (32-bit
// integers), and mean, m2, m3 and m4 (film.h) in double precision, each stored as a float and the float
// residual (x = hi + lo to within 2^-48 |x|). Its header names the render it belongs to.
#include "film.h"

#include <cstdint>
#include <string>
#include <vector>

// Which render a film file holds: a pass's share of the samples is the sample indices s with
// s % passes == pass - 1 (render.h), of `samples` per pixel in the whole render.
struct Film_Origin {
	std::string scene; // the scene file, as given on the command line
	uint64_t seed = 0;
	uint32_t samples = 0;
	uint32_t pass = 1, passes = 1; // 1 <= pass <= passes
};

struct Film_File {
	Film film;
	Film_Origin origin;
};

void write_film(const std::string& path, const Film& film, const Film_Origin& origin);
// Throws Input_Error naming the file when it is not a film file (e.g. an ordinary EXR image).
Film_File read_film(const std::string& path);

// The films of passes 1..N of one render, in any order, combined into the film of the whole render
// (Pixel_Stats::merge). Throws Input_Error, naming the file, if the films are not the passes of one
// render (another scene, seed, sample count, size or number of passes), a pass is given twice, or
// one is missing.
Film_File merge_films(const std::vector<std::string>& paths);
