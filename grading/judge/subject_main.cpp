// The subject: the program that runs a student's code for the judge (protocol.h). It is linked
// with the student's task N and the reference of the other six (cmake/lab.cmake) and started by
// the judge inside the sandbox, one fresh process per test case. It reads a request, runs the task
// functions on the request's inputs and writes back their raw outputs; it decides nothing.
//
// For debugging (./lab grade N --debug), `subject --replay FILE` answers the requests a judge
// saved in FILE and discards the answers, so the student's code can be stepped through in gdb.
//
// Before any of its own code runs (student code included), it locks itself to the code it was
// linked with: no exec, no new executable memory (no_new_code.h).
#include "no_new_code.h"
#include "protocol.h"
#include "wire.h"

// The task functions, per request: each task's answers.
#include "answers/task1.h"
#include "answers/task2.h"
#include "answers/task3.h"
#include "answers/task4.h"
#include "answers/task5.h"
#include "answers/task6.h"
#include "answers/task6_nee.h"
#include "answers/task7.h"
#include "answers/task8.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <tuple>

#include <fcntl.h>
#include <unistd.h>

namespace {

using namespace protocol;

void lock_to_linked_code() {
	if (!forbid_new_code()) {
		std::fprintf(stderr, "subject: the system refused the filter that keeps a subject to its own code (seccomp): %s\n",
		             std::strerror(errno));
		_exit(125);
	}
}
// The C library runs the .preinit_array before every static initializer of the program.
[[gnu::used, gnu::section(".preinit_array")]] void (*run_first)() = lock_to_linked_code;

// The answer to the request of kind `kind`, encoded (protocol::Requests lists them all).
template<class... Request> std::string serve_one_of(std::tuple<Request...>*, Kind kind, const std::string& payload) {
	std::string encoded;
	bool known = ((kind == Request::KIND ? (encoded = wire::encode(answer(wire::decode<Request>(payload))), true) : false) ||
	              ...);
	if (!known) throw wire::Malformed("unknown request kind " + std::to_string(uint32_t(kind)));
	return encoded;
}

std::string serve(Kind kind, const std::string& payload) {
	return serve_one_of(static_cast<Requests*>(nullptr), kind, payload);
}

// ---- Transport ----

bool read_all(int fd, void* data, size_t size) {
	char* p = static_cast<char*>(data);
	while (size > 0) {
		ssize_t n = read(fd, p, size);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) return false;
		p += n;
		size -= size_t(n);
	}
	return true;
}

void write_all(int fd, const void* data, size_t size) {
	const char* p = static_cast<const char*>(data);
	while (size > 0) {
		ssize_t n = write(fd, p, size);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) _exit(3); // the judge is gone
		p += n;
		size -= size_t(n);
	}
}

using wire::Request_Header;

// Reads one request; false at the end of the input.
bool read_request(int fd, Request_Header& header, std::string& payload) {
	char header_bytes[Request_Header::BYTES];
	if (!read_all(fd, header_bytes, sizeof header_bytes)) return false;
	header = wire::request_header(header_bytes);
	if (header.magic != MAGIC || header.length > MAX_PAYLOAD) {
		std::fprintf(stderr, "subject: not a judge's request\n");
		_exit(2);
	}
	payload.resize(header.length);
	return read_all(fd, payload.data(), payload.size());
}

// The request being answered (its questions repeat its header), and whether it is replayed.
Request_Header current_request;
bool replaying = false;

void write_answer(const Request_Header& request, Status status, const std::string& payload) {
	wire::Answer_Header header;
	header.kind = request.kind, header.sequence = request.sequence, header.status = uint32_t(status);
	std::string message = wire::message(header, payload);
	write_all(ANSWER_FD, message.data(), message.size());
}

Trace Judge_Answers::hit(uint32_t object, const Ray& ray) const {
	if (replaying) return Trace{}; // the judge's replies are not saved: every object is missed
	write_answer(current_request, Status::QUESTION, wire::encode(Object_Question{object, ray}));
	Request_Header reply;
	std::string payload;
	if (!read_request(REQUEST_FD, reply, payload) || reply.kind != current_request.kind ||
	    reply.sequence != current_request.sequence) {
		_exit(3); // the judge is gone, or not a judge
	}
	return wire::decode<Trace>(payload);
}

int serve_judge() {
	Request_Header& header = current_request;
	std::string payload;
	while (read_request(REQUEST_FD, header, payload)) {
		std::string answer;
		Status status = Status::OK;
		try {
			answer = serve(Kind(header.kind), payload);
		} catch (const std::exception& error) {
			status = Status::THREW;
			answer = error.what();
		}
		write_answer(header, status, answer);
	}
	return 0;
}

// Answers every request saved in `file` (the judge's --save-requests), printing what it runs.
int replay(const char* file) {
	int fd = open(file, O_RDONLY);
	if (fd < 0) {
		std::fprintf(stderr, "subject: cannot open %s: %s\n", file, std::strerror(errno));
		return 2;
	}
	replaying = true;
	Request_Header header;
	std::string payload;
	while (read_request(fd, header, payload)) {
		std::fprintf(stderr, "subject: request %u, %s (%s)\n", header.sequence, kind_name(Kind(header.kind)),
		             kind_functions(Kind(header.kind)));
		if (Kind(header.kind) == BVH_Instances::KIND) {
			std::fprintf(stderr, "subject: (the judge answered for its objects, which a replay cannot: every "
			                     "Instance::hit misses)\n");
		}
		serve(Kind(header.kind), payload);
	}
	std::fprintf(stderr, "subject: every request answered\n");
	return 0;
}

} // namespace

int main(int argc, char** argv) {
	wire::keep_large_buffers();
	if (argc == 3 && std::string(argv[1]) == "--replay") return replay(argv[2]);
	if (argc != 1) {
		std::fprintf(stderr, "usage: %s            (started by a judge, see grading/judge/protocol.h)\n"
		                     "       %s --replay FILE (answer the requests a judge saved, for a debugger)\n",
		             argv[0], argv[0]);
		return 2;
	}
	return serve_judge();
}
