#include "error.h"
#include "scene_loader.h"

#include <cstdio>

int main(int argc, char** argv) {
	if (argc < 2) return 2;
	try {
		Scene scene = load_scene(argv[1]);
	} catch (const Input_Error& e) {
		std::fprintf(stderr, "error: %s\n", e.what());
		return 1;
	}
}
