#include "output_file.h"
#include "error.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// "<path>: <what>: <the system's reason for errno `error`>"
[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
	throw Input_Error(path + ": " + what + ": " + std::strerror(error));
}

// Where the bytes of `path` go: a symbolic link's target, so that the link stays a link.
fs::path destination(const std::string& path) {
	std::error_code error;
	if (!fs::is_symlink(path, error)) return path;
	fs::path target = fs::canonical(path, error);
	return error ? fs::path(path) : target;
}

// Devices and pipes are written in place: only a regular file may be replaced by renaming.
bool is_special_file(const fs::path& file) {
	std::error_code error;
	fs::file_status status = fs::status(file, error);
	return fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

void remove_folders(const std::vector<fs::path>& folders) {
	std::error_code ignored;
	for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) fs::remove(*folder, ignored);
}

// Creates the missing folders above `file`; returns those it created, outermost first.
std::vector<fs::path> make_folders(const std::string& path, const fs::path& file) {
	std::vector<fs::path> missing;
	std::error_code error;
	for (fs::path folder = file.parent_path(); !folder.empty() && !fs::exists(folder, error);
	     folder = folder.parent_path()) {
		missing.insert(missing.begin(), folder);
	}
	for (size_t i = 0; i < missing.size(); i++) {
		if (!fs::create_directory(missing[i], error) && error) {
			remove_folders(std::vector<fs::path>(missing.begin(), missing.begin() + long(i)));
			fail(path, "cannot create the folder " + missing[i].string(), error.value());
		}
	}
	return missing;
}

// Writes all of `bytes` and closes `fd`; returns 0 or the errno of the first failure.
int write_and_close(int fd, const std::string& bytes) {
	int error = 0;
	for (size_t done = 0; done < bytes.size() && !error;) {
		ssize_t written = write(fd, bytes.data() + done, bytes.size() - done);
		if (written > 0) done += size_t(written);
		else if (written == 0) error = EIO;
		else if (errno != EINTR) error = errno;
	}
	if (close(fd) != 0 && !error) error = errno;
	return error;
}

// A new, empty file beside `file`, under a name no other file has, and the folders it needed:
// all removed again unless it is renamed to `file`.
class Temporary_File {
public:
	Temporary_File(const std::string& path, const fs::path& file) : file(file), made(make_folders(path, file)) {
		static std::atomic<unsigned> counter{0};
		while (fd < 0) {
			name = file.parent_path() / ("." + file.filename().string() + "." + std::to_string(getpid()) + "-" +
			                             std::to_string(counter++) + ".part");
			fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
			if (fd < 0 && errno != EEXIST) {
				int error = errno;
				remove_folders(made);
				fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
				fail(path, "cannot create a file in " + folder.string(), error);
			}
		}
	}
	~Temporary_File() {
		if (fd >= 0) close(fd);
		if (renamed) return;
		unlink(name.c_str());
		remove_folders(made);
	}
	Temporary_File(const Temporary_File&) = delete;
	Temporary_File& operator=(const Temporary_File&) = delete;

	// Writes the whole content and renames the file to its name; returns 0 or an errno.
	int commit(const std::string& bytes) {
		int error = write_and_close(fd, bytes);
		fd = -1;
		if (!error && std::rename(name.c_str(), file.c_str()) != 0) error = errno;
		renamed = !error;
		return error;
	}

private:
	fs::path file, name;
	std::vector<fs::path> made;
	int fd = -1;
	bool renamed = false;
};

} // namespace

void check_writable(const std::string& path) {
	fs::path file = destination(path);
	std::error_code error;
	if (fs::is_directory(file, error)) throw Input_Error(path + ": is a folder, expected a file name");
	if (is_special_file(file)) {
		int fd = open(file.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC); // (a pipe without reader: no wait)
		if (fd < 0) fail(path, "cannot open the file for writing", errno);
		close(fd);
		return;
	}
	Temporary_File probe(path, file); // and removed
}

void write_file(const std::string& path, const std::string& bytes) {
	fs::path file = destination(path);
	int error = 0;
	if (is_special_file(file)) {
		int fd = open(file.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
		if (fd < 0) fail(path, "cannot open the file for writing", errno);
		error = write_and_close(fd, bytes);
	} else {
		error = Temporary_File(path, file).commit(bytes);
	}
	if (error) fail(path, "cannot write the file", error);
}
