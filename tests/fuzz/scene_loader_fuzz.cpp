// libFuzzer target: load_scene on arbitrary bytes. Bad input must end in Input_Error (a message
// for the user); anything else (a crash, a sanitizer report, another exception) is a bug.
//
// The input is written as scene.json into a scratch directory that links the small files of
// scenes/meshes/ and scenes/hdri/, so that the corpus (copies of scenes/*.json) loads with them.
#include "error.h"
#include "scene_loader.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {
namespace fs = std::filesystem;

// A directory deleted with its contents when the process exits.
struct Scratch {
	fs::path path;
	~Scratch() {
		std::error_code ignored;
		fs::remove_all(path, ignored);
	}
};

// The scratch directory, made once per process.
const fs::path& scratch_dir() {
	static const Scratch dir{[] {
		fs::path d = fs::temp_directory_path() / ("pathtracer-lab-fuzz-" + std::to_string(getpid()));
		fs::create_directories(d);
		// Only the small files: a 10^5-triangle mesh takes seconds to load under the sanitizers,
		// which libFuzzer would report as a hang. The others are missing (an Input_Error).
		for (const char* sub : {"meshes", "hdri"}) {
			fs::create_directories(d / sub);
			for (const auto& entry : fs::directory_iterator(fs::path(LAB_SCENES_DIR) / sub)) {
				std::error_code ignored;
				if (entry.file_size() <= 400000) fs::create_symlink(entry.path(), d / sub / entry.path().filename(), ignored);
			}
		}
		return d;
	}()};
	return dir.path;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
	fs::path file = scratch_dir() / "scene.json";
	{
		std::ofstream out(file, std::ios::binary | std::ios::trunc);
		out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
	}
	try {
		Scene scene = load_scene(file.string());
	} catch (const Input_Error&) {
		// Rejected with a message: what bad input should get.
	}
	return 0;
}
