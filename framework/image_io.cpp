#include "image_io.h"
#include "error.h"

void write_png(const std::string& path, const HDR_Image&, float) {
	throw Input_Error(path + ": PNG output is not written yet");
}
void write_exr(const std::string& path, const HDR_Image&) {
	throw Input_Error(path + ": EXR output is not written yet");
}
HDR_Image read_image(const std::string& path) {
	throw Input_Error(path + ": image input is not written yet");
}
