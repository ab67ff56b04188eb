#pragma once
// The viewer's HTTP server (cpp-httplib, Debian's libcpp-httplib-dev): the page and its API, for
// the session (viewer_session.h). Safe by default: it listens on 127.0.0.1 only, and every
// request must carry the token the viewer printed in its URL (?token=...); a malformed request
// gets a 4xx answer with a message naming what was expected.
//
//   GET  /                    the page (also /viewer.js, /viewer.css)
//   GET  /api/state           settings, each side's progress, the comparison (JSON)
//   GET  /api/events          server-sent events: state, frame, comparison, renderer, build,
//                             grade, graded
//   GET  /api/image?side=student|reference&layer=mean|variance|non_finite|z
//                             the latest frame's layer as bytes (X-Width, X-Height, X-Samples)
//   GET  /api/path?side=&x=&y=[&samples=N][&brightest=K]
//                             the pixel's paths (--follow-pixel --follow-format json)
//   POST /api/pause, /api/resume
//   POST /api/restart[?seed=S][&view=V][&scene=NAME.json]
//   POST /api/grade?task=N    runs the grader of task N; its lines come as events
//   POST /api/snapshot?side=&name=NAME.png[&exposure=STOPS]
//                             writes the side's picture into the output folder
#include "viewer_session.h"

#include <memory>
#include <string>

namespace httplib {
class Server;
}

class Viewer_Server {
public:
	Viewer_Server(Viewer_Session& session, Event_Hub& hub, std::string token);
	~Viewer_Server();

	// Binds 127.0.0.1:port (0: any free port) and returns the port; throws std::runtime_error if it
	// cannot.
	int bind(int port);
	// Serves until stop() (from another thread or a signal handler's thread).
	void serve();
	void stop();

	const std::string& url_token() const {
		return token;
	}

private:
	void add_routes();

	Viewer_Session& session;
	Event_Hub& hub;
	std::string token;
	std::unique_ptr<httplib::Server> server;
};

// 32 hexadecimal digits from the system's random source: the token of the viewer's URL.
std::string new_token();
