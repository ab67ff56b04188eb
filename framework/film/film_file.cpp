#include "film_file.h"
#include "error.h"
#include "exr_encoding.h"
#include "output_file.h"

// The Debian package ships tinyexr compiled: include declarations only.
#include <tinyexr.h>

#include <algorithm>
#include <map>
#include <memory>

namespace {


// A double as two floats, hi + lo.
float high_part(double x) {
	return float(x);
}
float low_part(double x) {
	return float(x - double(float(x)));
}

std::vector<Exr_Channel> channels_of(const Film& film) {
	const char* rgb[] = {"R", "G", "B"};
	std::vector<Exr_Channel> channels;
	auto add_double = [&](const std::string& name, const std::string& residual, int c, glm::dvec3 Pixel_Stats::*field) {
		Exr_Channel hi{name, {}, {}}, lo{residual, {}, {}};
		for (const Pixel_Stats& p : film.pixels) {
			hi.floats.push_back(high_part((p.*field)[c]));
			lo.floats.push_back(low_part((p.*field)[c]));
		}
		channels.push_back(std::move(hi));
		channels.push_back(std::move(lo));
	};
	for (int c = 0; c < 3; c++) {
		add_double(rgb[c], std::string("mean_residual.") + rgb[c], c, &Pixel_Stats::mean);
		add_double(std::string("m2.") + rgb[c], std::string("m2_residual.") + rgb[c], c, &Pixel_Stats::m2);
		add_double(std::string("m3.") + rgb[c], std::string("m3_residual.") + rgb[c], c, &Pixel_Stats::m3);
		add_double(std::string("m4.") + rgb[c], std::string("m4_residual.") + rgb[c], c, &Pixel_Stats::m4);
	}
	Exr_Channel count{"count", {}, {}}, non_finite{"non_finite", {}, {}};
	for (const Pixel_Stats& p : film.pixels) {
		count.integers.push_back(p.count);
		non_finite.integers.push_back(p.non_finite);
	}
	channels.push_back(std::move(count));
	channels.push_back(std::move(non_finite));
	// OpenEXR lists channels by name.
	std::sort(channels.begin(), channels.end(), [](const Exr_Channel& a, const Exr_Channel& b) { return a.name < b.name; });
	return channels;
}

std::map<std::string, std::string> attributes_of(const Film_Origin& origin) {
	return {{"lab_scene", origin.scene},
	        {"lab_seed", std::to_string(origin.seed)},
	        {"lab_samples", std::to_string(origin.samples)},
	        {"lab_pass", std::to_string(origin.pass) + "/" + std::to_string(origin.passes)}};
}

uint64_t parse_number(const std::string& path, const std::string& name, const std::string& text) {
	size_t used = 0;
	uint64_t value = 0;
	try {
		value = std::stoull(text, &used);
	} catch (const std::exception&) {
		used = 0;
	}
	if (used == 0 || used != text.size()) throw Input_Error(path + ": film attribute " + name + " is not a number: '" + text + "'");
	return value;
}

Film_Origin origin_of(const std::string& path, const std::map<std::string, std::string>& attributes) {
	auto get = [&](const std::string& name) {
		auto found = attributes.find(name);
		if (found == attributes.end()) {
			throw Input_Error(path + ": not a film file (no attribute " + name +
			                  "; film files are written by the renderer's --film)");
		}
		return found->second;
	};
	Film_Origin origin;
	origin.scene = get("lab_scene");
	origin.seed = parse_number(path, "lab_seed", get("lab_seed"));
	origin.samples = uint32_t(parse_number(path, "lab_samples", get("lab_samples")));
	std::string pass = get("lab_pass");
	size_t slash = pass.find('/');
	if (slash == std::string::npos) throw Input_Error(path + ": film attribute lab_pass is not I/N: '" + pass + "'");
	origin.pass = uint32_t(parse_number(path, "lab_pass", pass.substr(0, slash)));
	origin.passes = uint32_t(parse_number(path, "lab_pass", pass.substr(slash + 1)));
	if (origin.pass < 1 || origin.pass > origin.passes) {
		throw Input_Error(path + ": film attribute lab_pass is " + pass + "; expected I/N with 1 <= I <= N");
	}
	return origin;
}

} // namespace

void write_film(const std::string& path, const Film& film, const Film_Origin& origin) {
	if (film.w == 0 || film.h == 0) throw Input_Error(path + ": cannot write an empty film");
	write_file(path, encode_exr(path, "the film", film.w, film.h, channels_of(film), Exr_Compression::zip,
	                            attributes_of(origin)));
}

Film_File read_film(const std::string& path) {
	EXRVersion version;
	if (ParseEXRVersionFromFile(&version, path.c_str()) != TINYEXR_SUCCESS) {
		throw Input_Error(path + ": cannot read the film (not an OpenEXR file, or it does not exist)");
	}
	EXRHeader header;
	InitEXRHeader(&header);
	const char* message = nullptr;
	if (ParseEXRHeaderFromFile(&header, &version, path.c_str(), &message) != TINYEXR_SUCCESS) {
		throw Input_Error(path + ": cannot read the film: " + take_exr_message(message));
	}
	std::unique_ptr<EXRHeader, int (*)(EXRHeader*)> header_owner(&header, FreeEXRHeader);
	std::map<std::string, std::string> attributes;
	for (int i = 0; i < header.num_custom_attributes; i++) {
		const EXRAttribute& a = header.custom_attributes[i];
		attributes[a.name] = std::string(reinterpret_cast<const char*>(a.value), size_t(std::max(a.size, 0)));
	}
	Film_Origin origin = origin_of(path, attributes);
	for (int c = 0; c < header.num_channels; c++) header.requested_pixel_types[c] = header.pixel_types[c];

	EXRImage image;
	InitEXRImage(&image);
	if (LoadEXRImageFromFile(&image, &header, path.c_str(), &message) != TINYEXR_SUCCESS) {
		throw Input_Error(path + ": cannot read the film: " + take_exr_message(message));
	}
	std::unique_ptr<EXRImage, int (*)(EXRImage*)> image_owner(&image, FreeEXRImage);
	if (image.images == nullptr) throw Input_Error(path + ": a film is stored in scanlines, not tiles");
	Film film(uint32_t(image.width), uint32_t(image.height));
	std::map<std::string, int> index;
	for (int c = 0; c < header.num_channels; c++) index[header.channels[c].name] = c;
	auto plane = [&](const std::string& name, int type) {
		auto found = index.find(name);
		if (found == index.end() || header.pixel_types[found->second] != type) {
			throw Input_Error(path + ": a film needs the channel " + name + " (" +
			                  (type == TINYEXR_PIXELTYPE_UINT ? "32-bit integers" : "32-bit floats") + ")");
		}
		return image.images[found->second];
	};
	auto read_double = [&](const std::string& hi_name, const std::string& lo_name, int c, glm::dvec3 Pixel_Stats::*field) {
		const float* hi = reinterpret_cast<const float*>(plane(hi_name, TINYEXR_PIXELTYPE_FLOAT));
		const float* lo = reinterpret_cast<const float*>(plane(lo_name, TINYEXR_PIXELTYPE_FLOAT));
		for (size_t i = 0; i < film.pixels.size(); i++) (film.pixels[i].*field)[c] = double(hi[i]) + double(lo[i]);
	};
	const char* rgb[] = {"R", "G", "B"};
	for (int c = 0; c < 3; c++) {
		read_double(rgb[c], std::string("mean_residual.") + rgb[c], c, &Pixel_Stats::mean);
		read_double(std::string("m2.") + rgb[c], std::string("m2_residual.") + rgb[c], c, &Pixel_Stats::m2);
		read_double(std::string("m3.") + rgb[c], std::string("m3_residual.") + rgb[c], c, &Pixel_Stats::m3);
		read_double(std::string("m4.") + rgb[c], std::string("m4_residual.") + rgb[c], c, &Pixel_Stats::m4);
	}
	const uint32_t* count = reinterpret_cast<const uint32_t*>(plane("count", TINYEXR_PIXELTYPE_UINT));
	const uint32_t* non_finite = reinterpret_cast<const uint32_t*>(plane("non_finite", TINYEXR_PIXELTYPE_UINT));
	for (size_t i = 0; i < film.pixels.size(); i++) {
		film.pixels[i].count = count[i];
		film.pixels[i].non_finite = non_finite[i];
	}
	return Film_File{std::move(film), origin};
}

Film_File merge_films(const std::vector<std::string>& paths) {
	if (paths.empty()) throw Input_Error("merge: no film files given");
	Film_File merged = read_film(paths.front());
	const Film_Origin first = merged.origin;
	std::vector<std::string> pass_files(first.passes);
	pass_files[first.pass - 1] = paths.front();
	auto describe = [](const Film_Origin& o) {
		return o.scene + ", seed " + std::to_string(o.seed) + ", " + std::to_string(o.samples) + " samples, " +
		       std::to_string(o.passes) + " passes";
	};
	for (size_t i = 1; i < paths.size(); i++) {
		Film_File part = read_film(paths[i]);
		const Film_Origin& o = part.origin;
		if (o.scene != first.scene || o.seed != first.seed || o.samples != first.samples || o.passes != first.passes ||
		    part.film.w != merged.film.w || part.film.h != merged.film.h) {
			throw Input_Error(paths[i] + ": a pass of another render (" + describe(o) + ", " +
			                  std::to_string(part.film.w) + " x " + std::to_string(part.film.h) + ") than " +
			                  paths.front() + " (" + describe(first) + ", " + std::to_string(merged.film.w) + " x " +
			                  std::to_string(merged.film.h) + ")");
		}
		if (!pass_files[o.pass - 1].empty()) {
			throw Input_Error(paths[i] + ": pass " + std::to_string(o.pass) + " is already in " + pass_files[o.pass - 1]);
		}
		pass_files[o.pass - 1] = paths[i];
		for (size_t p = 0; p < merged.film.pixels.size(); p++) merged.film.pixels[p].merge(part.film.pixels[p]);
	}
	for (uint32_t pass = 1; pass <= first.passes; pass++) {
		if (pass_files[pass - 1].empty()) {
			throw Input_Error("merge: pass " + std::to_string(pass) + " of " + std::to_string(first.passes) + " of " +
			                  describe(first) + " is missing");
		}
	}
	merged.origin.pass = merged.origin.passes = 1;
	return merged;
}
