#pragma once
// A fresh, empty directory for a test's files, deleted with everything in it when the test ends.
#include <atomic>
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

class Temp_Dir {
public:
	Temp_Dir() {
		static std::atomic<unsigned> counter{0};
		std::string name = "pathtracer-lab-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
		path_ = std::filesystem::temp_directory_path() / name;
		std::filesystem::remove_all(path_);
		std::filesystem::create_directories(path_);
	}
	~Temp_Dir() {
		std::error_code ignored;
		std::filesystem::remove_all(path_, ignored);
	}
	Temp_Dir(const Temp_Dir&) = delete;
	Temp_Dir& operator=(const Temp_Dir&) = delete;

	const std::filesystem::path& path() const {
		return path_;
	}
	// The path of `name` inside the directory, as a string.
	std::string file(const std::string& name) const {
		return (path_ / name).string();
	}

private:
	std::filesystem::path path_;
};
