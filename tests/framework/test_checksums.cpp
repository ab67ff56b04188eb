// The checksums with which the graders check their reference images and test data
// (tests/support/sha256.h, graded_images.h).
#include "error.h"
#include "graded_images.h"
#include "sha256.h"
#include "temp_dir.h"

#include "lab_catch2.h"

#include <fstream>

TEST_CASE("SHA-256 gives the FIPS 180-4 example digests", "[framework][checksum]") {
	CHECK(sha256_of_bytes("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
	CHECK(sha256_of_bytes("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
	CHECK(sha256_of_bytes("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
	      "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
	CHECK(sha256_of_bytes(std::string(1000000, 'a')) ==
	      "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("a checked file that changed after its checksum was recorded is an error", "[framework][checksum]") {
	Temp_Dir dir;
	std::string file = dir.file("reference.exr"), sums = dir.file("SHA256SUMS");
	std::ofstream(file) << "the reference";
	std::ofstream(sums) << sha256_of_file(file) << "  " << file << "\n";
	CHECK_NOTHROW(verify_checksum(file, sums));
	std::ofstream(file) << "a forged reference";
	CHECK_THROWS_WITH(verify_checksum(file, sums), contains_text("checksum mismatch"));
	CHECK_THROWS_WITH(verify_checksum(dir.file("other.exr"), sums), contains_text("has no checksum"));
}

TEST_CASE("the shipped graded scenes and references match their recorded checksums", "[framework][checksum]") {
	for (const Graded_Scene& scene : graded_scenes()) {
		CAPTURE(scene.name);
		CHECK_NOTHROW(verify_checksum(graded_scene_file(scene.name)));
		for (const char* suffix : {".json", "_mean.exr", "_var.exr"}) {
			CHECK_NOTHROW(verify_checksum(reference_file(scene.name, suffix)));
		}
	}
}
