// lab_viewer: the live lab (./lab view). Serves the page on 127.0.0.1 and prints its URL at once:
//   lab_viewer SCENE --reference-renderer PATH [--student-renderer PATH | --reference-only]
//              [--port N] [--out-dir DIR] [--student-dir DIR --lab PATH --build-dir DIR
//              [--rebuild-target T]] [--max-spp N] [--threads T] [--seed S]
// ./lab view chooses these; they are documented in viewer_options.cpp.
#include "error.h"
#include "viewer_options.h"
#include "viewer_server.h"

#include <csignal>
#include <iostream>
#include <pthread.h>
#include <thread>

int main(int argc, char** argv) {
	Viewer_Options options;
	try {
		options = parse_viewer_options(std::vector<std::string>(argv, argv + argc));
	} catch (const Input_Error& e) {
		std::cerr << "lab_viewer: " << e.what() << "\n" << viewer_usage();
		return 2;
	}
	// Ctrl-C (or a test's SIGTERM) stops the server, which stops the renderers, from one thread
	// that waits for it; every other thread has the signals blocked.
	sigset_t stop_signals;
	sigemptyset(&stop_signals);
	sigaddset(&stop_signals, SIGINT);
	sigaddset(&stop_signals, SIGTERM);
	pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
	std::signal(SIGPIPE, SIG_IGN); // a renderer or a page that went away is an error, not an end

	try {
		Event_Hub hub;
		Viewer_Session session(options.session, hub);
		Viewer_Server server(session, hub, new_token());
		int port = server.bind(options.port);
		std::string url = "http://127.0.0.1:" + std::to_string(port) + "/?token=" + server.url_token();
		std::cout << "lab view: open " << url << "\n"
		          << "  (on a remote machine: ssh -L " << port << ":127.0.0.1:" << port
		          << " HOST, then open the same URL here; Ctrl-C stops the viewer)\n"
		          << std::flush;
		session.start();
		std::thread stopper([&] {
			int signal = 0;
			sigwait(&stop_signals, &signal);
			server.stop();
		});
		server.serve();
		pthread_kill(stopper.native_handle(), SIGTERM); // (if the server stopped by itself)
		stopper.join();
	} catch (const std::exception& e) {
		std::cerr << "lab_viewer: " << e.what() << "\n";
		return 1;
	}
	return 0;
}
