#include "landlock.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/stat.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace {

// The access rights of Landlock ABI 1 (Linux 5.13) for files and folders; later ABIs add rights
// (refer, truncate, ioctl on devices) that a ruleset which does not name them leaves allowed, so
// they are added where the kernel knows them.
constexpr __u64 READ = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
constexpr __u64 WRITE_ABI1 = LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_REMOVE_DIR |
                             LANDLOCK_ACCESS_FS_REMOVE_FILE | LANDLOCK_ACCESS_FS_MAKE_CHAR |
                             LANDLOCK_ACCESS_FS_MAKE_DIR | LANDLOCK_ACCESS_FS_MAKE_REG |
                             LANDLOCK_ACCESS_FS_MAKE_SOCK | LANDLOCK_ACCESS_FS_MAKE_FIFO |
                             LANDLOCK_ACCESS_FS_MAKE_BLOCK | LANDLOCK_ACCESS_FS_MAKE_SYM;

// LANDLOCK_ACCESS_FS_TRUNCATE (ABI 3, Linux 6.2), which Debian 12's kernel headers predate.
constexpr __u64 ACCESS_FS_TRUNCATE = __u64(1) << 14;

__u64 write_rights(int abi) {
	__u64 rights = WRITE_ABI1;
	if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;
	if (abi >= 3) rights |= ACCESS_FS_TRUNCATE;
	return rights;
}

// Rights that apply to folders only; a rule on a file may not name them.
constexpr __u64 FOLDER_ONLY = LANDLOCK_ACCESS_FS_READ_DIR | LANDLOCK_ACCESS_FS_REMOVE_DIR |
                              LANDLOCK_ACCESS_FS_REMOVE_FILE | LANDLOCK_ACCESS_FS_MAKE_CHAR |
                              LANDLOCK_ACCESS_FS_MAKE_DIR | LANDLOCK_ACCESS_FS_MAKE_REG |
                              LANDLOCK_ACCESS_FS_MAKE_SOCK | LANDLOCK_ACCESS_FS_MAKE_FIFO |
                              LANDLOCK_ACCESS_FS_MAKE_BLOCK | LANDLOCK_ACCESS_FS_MAKE_SYM |
                              LANDLOCK_ACCESS_FS_REFER;

} // namespace

Landlock_Rules::Landlock_Rules(const std::vector<std::string>& readable, const std::vector<std::string>& writable) {
	abi_ = int(syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION));
	if (abi_ < 1) {
		problem_ = errno == ENOSYS ? "the kernel has no Landlock (Linux >= 5.13)" : "Landlock is disabled in this kernel";
		abi_ = 0;
		return;
	}
	__u64 write = write_rights(abi_);
	landlock_ruleset_attr attributes{};
	attributes.handled_access_fs = READ | write;
	int made = int(syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0));
	if (made < 0) {
		problem_ = std::string("cannot make a Landlock ruleset: ") + std::strerror(errno);
		return;
	}
	// Above the low descriptors, which a child rearranges between fork and exec.
	ruleset = fcntl(made, F_DUPFD_CLOEXEC, 10);
	close(made);
	auto allow = [&](const std::string& path, __u64 rights) {
		int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
		if (fd < 0) return; // not on this system
		struct stat info {};
		if (fstat(fd, &info) == 0 && !S_ISDIR(info.st_mode)) rights &= ~FOLDER_ONLY;
		landlock_path_beneath_attr rule{rights, fd};
		syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
		close(fd);
	};
	for (const std::string& path : readable) allow(path, READ);
	for (const std::string& path : writable) allow(path, READ | write);
}

Landlock_Rules::~Landlock_Rules() {
	if (ruleset >= 0) close(ruleset);
}

bool Landlock_Rules::apply_to_self() const {
	if (ruleset < 0) return false;
	if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
	return syscall(SYS_landlock_restrict_self, ruleset, 0) == 0;
}

std::vector<std::string> system_files() {
	return {"/usr", "/lib", "/lib64", "/lib32", "/bin", "/sbin", "/etc/ld.so.cache", "/sys/devices/system/cpu",
	        "/dev/null", "/dev/zero", "/dev/urandom"};
}
