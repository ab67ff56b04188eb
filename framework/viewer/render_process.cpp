#include "render_process.h"

#include <istream>
#include <streambuf>
#include <unistd.h>

namespace {
// An input stream buffer over a file descriptor (the renderer's standard output).
class Fd_Buffer : public std::streambuf {
public:
	explicit Fd_Buffer(int fd) : fd(fd) {
	}

protected:
	int_type underflow() override {
		ssize_t n;
		do {
			n = ::read(fd, buffer, sizeof buffer);
		} while (n < 0 && errno == EINTR);
		if (n <= 0) return traits_type::eof();
		setg(buffer, buffer, buffer + n);
		return traits_type::to_int_type(buffer[0]);
	}

	std::streamsize xsgetn(char* data, std::streamsize count) override {
		std::streamsize done = 0;
		while (done < count) {
			std::streamsize buffered = egptr() - gptr();
			if (buffered == 0) {
				if (underflow() == traits_type::eof()) break;
				continue;
			}
			std::streamsize n = std::min(buffered, count - done);
			std::copy(gptr(), gptr() + n, data + done);
			gbump(int(n));
			done += n;
		}
		return done;
	}

private:
	int fd;
	char buffer[1 << 16];
};
} // namespace

Render_Process::Render_Process(const std::vector<std::string>& argv, Frame_Handler on_frame_, End_Handler on_end_)
	: child(argv, false), on_frame(std::move(on_frame_)), on_end(std::move(on_end_)) {
	error_reader = std::thread([this] { errors = read_all(child.error_fd()); });
	frame_reader = std::thread([this] { read_frames(); });
}

Render_Process::~Render_Process() {
	stopping = true;
	child.kill();
	if (frame_reader.joinable()) frame_reader.join();
	if (error_reader.joinable()) error_reader.join();
}

void Render_Process::read_frames() {
	Fd_Buffer buffer(child.output_fd());
	std::istream in(&buffer);
	std::string problem;
	try {
		for (;;) {
			auto frame = std::make_shared<Film_Frame>();
			if (!read_frame(in, *frame)) break;
			on_frame(std::move(frame));
		}
	} catch (const std::exception& e) {
		problem = e.what();
	}
	if (stopping) return;
	if (!problem.empty()) child.kill(); // a broken stream: the renderer is of no more use
	error_reader.join();
	int status = child.wait();
	on_end(status, problem.empty() ? errors : errors + problem + "\n");
}
