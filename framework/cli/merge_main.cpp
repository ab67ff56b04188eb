// merge_films (./lab merge): the passes of a render split over machines (--pass P/N --film FILE.exr)
// combined into the film of the whole render, and its images. The result is the single render's up
// to the order of the sums (film_file.h).
//
//   merge_films PASS.exr... [--film FILM.exr] [--exr MEAN.exr] [--variance VARIANCE.exr] [--out IMAGE.png]
#include "error.h"
#include "film_file.h"
#include "image_io.h"
#include "output_file.h"

#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {
const char* USAGE =
	"usage: merge_films PASS.exr... [--film FILM.exr] [--exr MEAN.exr] [--variance VARIANCE.exr]\n"
	"                   [--out IMAGE.png]\n"
	"Merges the film files of passes 1..N of one render (the renderer's --pass P/N --film FILE.exr),\n"
	"in any order, into the whole render's film (--film), mean (--exr), per-sample variance\n"
	"(--variance) or picture (--out). At least one output.\n";
}

int main(int argc, char** argv) {
	std::vector<std::string> passes;
	std::map<std::string, std::string> outputs; // option -> file
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		if (arg == "--help" || arg == "-h") {
			std::cout << USAGE;
			return 0;
		}
		if (arg == "--film" || arg == "--exr" || arg == "--variance" || arg == "--out") {
			if (i + 1 == argc) {
				std::cerr << "merge_films: " << arg << " needs a file name\n" << USAGE;
				return 2;
			}
			outputs[arg] = argv[++i];
		} else if (arg.rfind("--", 0) == 0) {
			std::cerr << "merge_films: unknown option '" << arg << "'\n" << USAGE;
			return 2;
		} else {
			passes.push_back(arg);
		}
	}
	if (passes.empty() || outputs.empty()) {
		std::cerr << "merge_films: give the passes' film files and at least one output\n" << USAGE;
		return 2;
	}
	try {
		for (const auto& [option, path] : outputs) check_writable(path);
		Film_File merged = merge_films(passes);
		for (const auto& [option, path] : outputs) {
			if (option == "--film") write_film(path, merged.film, merged.origin);
			if (option == "--exr") write_exr(path, merged.film.mean());
			if (option == "--variance") write_exr(path, merged.film.variance());
			if (option == "--out") write_png(path, merged.film.mean());
			std::cout << "wrote " << path << "\n";
		}
		std::cout << "merged " << passes.size() << " passes of " << merged.origin.scene << ": " << merged.film.w << " x "
		          << merged.film.h << " pixels, " << merged.origin.samples << " samples each, seed "
		          << merged.origin.seed << "\n";
	} catch (const Input_Error& e) {
		std::cerr << "merge_films: " << e.what() << "\n";
		return 1;
	}
}
