#include "report_record.h"

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <utility>

namespace report {

namespace {
std::string environment(const char* name) {
	const char* value = std::getenv(name);
	return value ? value : "";
}

std::string executable_name() {
	std::error_code error;
	return std::filesystem::read_symlink("/proc/self/exe", error).filename().string();
}

std::vector<nlohmann::ordered_json>& attachments() {
	static std::vector<nlohmann::ordered_json> items;
	return items;
}
} // namespace

bool enabled() {
	return !directory().empty();
}

std::string directory() {
	return environment("LAB_REPORT_DIR");
}

std::string task_name() {
	std::string task = environment("LAB_REPORT_TASK");
	if (!task.empty()) return "task" + task;
	std::string executable = executable_name();
	std::smatch match;
	if (std::regex_search(executable, match, std::regex("task([1-8])"))) return "task" + match[1].str();
	return executable;
}

std::string file(const std::string& name) {
	return (std::filesystem::path(directory()) / name).string();
}

void attach(nlohmann::ordered_json item) {
	attachments().push_back(std::move(item));
}

std::vector<nlohmann::ordered_json> take_attachments() {
	return std::exchange(attachments(), {});
}

} // namespace report
