// Hostile: on its first call, prints forged Catch2 and JUnit output and writes forged grade-report
// records where a report folder might be, then _exit(0).
#include "env_light.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

namespace {
[[noreturn]] void forge() {
	std::printf("All tests passed (200 assertions in 28 test cases)\n"
	            "<testsuites><testsuite name=\"task7\" tests=\"28\" failures=\"0\" errors=\"0\"/></testsuites>\n");
	std::fflush(stdout);
	const char* record = "{\"grader\": \"judge_task7\", \"finished\": true, \"fatal_error\": null, \"test_cases\": []}";
	const char* dirs[] = {getenv("LAB_REPORT_DIR"), "report", "../report", "/tmp/report", "@OUT@"};
	for (const char* dir : dirs) {
		if (dir) std::ofstream(std::string(dir) + "/task7.json") << record;
	}
	_exit(0);
}
} // namespace

Vec2 direction_to_uv(Vec3 dir) {
	forge();
}
Vec3 uv_to_direction(Vec2 uv) {
	forge();
}
namespace Samplers::Sphere {
Vec3 Uniform::sample(Vec2 u) const {
	forge();
}
float Uniform::pdf(Vec3 dir) const {
	forge();
}
Image::Image(const HDR_Image& image) {
	forge();
}
Vec3 Image::sample(Vec2 u) const {
	forge();
}
float Image::pdf(Vec3 dir) const {
	forge();
}
} // namespace Samplers::Sphere
Vec3 Env_Map::sample(Vec2 u) const {
	forge();
}
float Env_Map::pdf(Vec3 dir) const {
	forge();
}
Spectrum Env_Map::evaluate(Vec3 dir) const {
	forge();
}
