#pragma once
// OpenEXR files through tinyexr: the one encoder of the lab's EXR files (image_io.h's images,
// film_file.h's films), and tinyexr's error messages.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

// One channel of a file: its name and, per pixel (rows top to bottom), a 32-bit float or a 32-bit
// unsigned integer.
struct Exr_Channel {
	std::string name;
	std::vector<float> floats;
	std::vector<uint32_t> integers; // used where `floats` is empty
};

enum class Exr_Compression { none, zip };

// The bytes of a w x h OpenEXR file of `channels`, in the order given (OpenEXR readers expect them
// sorted by name), with string `attributes`. Throws Input_Error("<path>: cannot encode <what>: ...").
std::string encode_exr(const std::string& path, const std::string& what, uint32_t w, uint32_t h,
                       const std::vector<Exr_Channel>& channels, Exr_Compression compression,
                       const std::map<std::string, std::string>& attributes = {});

// The text of a message tinyexr allocated, which it frees ("unknown error" for none).
std::string take_exr_message(const char* message);
