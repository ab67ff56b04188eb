#include "scene_loader.h"
#include "error.h"

Scene load_scene(const std::string& path) {
	throw Input_Error(path + ": scene loading is not written yet");
}
