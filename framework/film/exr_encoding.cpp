#include "exr_encoding.h"
#include "error.h"

// The Debian package ships tinyexr compiled: include declarations only.
#include <tinyexr.h>

#include <cstdlib>
#include <cstring>

std::string encode_exr(const std::string& path, const std::string& what, uint32_t w, uint32_t h,
                       const std::vector<Exr_Channel>& channels, Exr_Compression compression,
                       const std::map<std::string, std::string>& attributes) {
	size_t count = channels.size();
	std::vector<EXRChannelInfo> infos(count);
	std::vector<int> types(count);
	std::vector<const unsigned char*> planes(count);
	for (size_t c = 0; c < count; c++) {
		std::strncpy(infos[c].name, channels[c].name.c_str(), sizeof infos[c].name - 1);
		bool integer = channels[c].floats.empty();
		types[c] = integer ? TINYEXR_PIXELTYPE_UINT : TINYEXR_PIXELTYPE_FLOAT;
		infos[c].pixel_type = types[c];
		planes[c] = integer ? reinterpret_cast<const unsigned char*>(channels[c].integers.data())
		                    : reinterpret_cast<const unsigned char*>(channels[c].floats.data());
	}
	std::vector<EXRAttribute> custom;
	for (const auto& [name, value] : attributes) {
		EXRAttribute exr{};
		std::strncpy(exr.name, name.c_str(), sizeof exr.name - 1);
		std::strcpy(exr.type, "string");
		exr.value = reinterpret_cast<unsigned char*>(const_cast<char*>(value.data())); // tinyexr reads it only
		exr.size = int(value.size());
		custom.push_back(exr);
	}

	EXRHeader header;
	InitEXRHeader(&header);
	header.num_channels = int(count);
	header.channels = infos.data();
	header.pixel_types = types.data();
	header.requested_pixel_types = types.data();
	header.compression_type =
		compression == Exr_Compression::zip ? TINYEXR_COMPRESSIONTYPE_ZIP : TINYEXR_COMPRESSIONTYPE_NONE;
	header.num_custom_attributes = int(custom.size());
	header.custom_attributes = custom.data();
	EXRImage image;
	InitEXRImage(&image);
	image.num_channels = int(count);
	image.images = const_cast<unsigned char**>(planes.data()); // tinyexr reads them only
	image.width = int(w);
	image.height = int(h);

	unsigned char* memory = nullptr;
	const char* message = nullptr;
	size_t size = SaveEXRImageToMemory(&image, &header, &memory, &message);
	if (size == 0) throw Input_Error(path + ": cannot encode " + what + ": " + take_exr_message(message));
	std::string bytes(reinterpret_cast<char*>(memory), size);
	std::free(memory);
	return bytes;
}

std::string take_exr_message(const char* message) {
	std::string text = message ? message : "unknown error";
	if (message) FreeEXRErrorMessage(message);
	return text;
}
