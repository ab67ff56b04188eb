#include "viewer_server.h"
#include "decimal.h"
#include "page_files.h"

#include <httplib.h>

#include <charconv>
#include <fstream>

namespace {
const char* content_type(std::string_view name) {
	if (name.size() >= 3 && name.substr(name.size() - 3) == ".js") return "text/javascript; charset=utf-8";
	if (name.size() >= 4 && name.substr(name.size() - 4) == ".css") return "text/css; charset=utf-8";
	return "text/html; charset=utf-8";
}

// Equal without telling, by the time it takes, how much of the token was right.
bool same_token(const std::string& a, const std::string& b) {
	if (a.size() != b.size()) return false;
	unsigned char difference = 0;
	for (size_t i = 0; i < a.size(); i++) difference |= static_cast<unsigned char>(a[i] ^ b[i]);
	return difference == 0;
}

void send_error(httplib::Response& res, int status, const std::string& message) {
	res.status = status;
	res.set_content(nlohmann::json{{"error", message}}.dump() + "\n", "application/json");
}

void send_json(httplib::Response& res, const nlohmann::json& value) {
	res.set_content(value.dump(), "application/json");
}

// A query parameter that must be there.
std::string required(const httplib::Request& req, const std::string& name, const std::string& expected) {
	if (!req.has_param(name)) throw Request_Error(400, "missing parameter " + name + " (expected " + expected + ")");
	return req.get_param_value(name);
}

// A whole number from min to max, or Request_Error(400) naming the parameter.
template<typename T> T whole(const std::string& name, const std::string& text, T min, T max) {
	T value{};
	auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
	if (status != std::errc() || end != text.data() + text.size() || value < min || value > max) {
		throw Request_Error(400, name + ": expected a whole number from " + std::to_string(min) + " to " +
		                             std::to_string(max) + ", got '" + text + "'");
	}
	return value;
}

template<typename T>
T whole_or(const httplib::Request& req, const std::string& name, T fallback, T min, T max) {
	return req.has_param(name) ? whole<T>(name, req.get_param_value(name), min, max) : fallback;
}

float stops(const httplib::Request& req) {
	if (!req.has_param("exposure")) return 0.0f;
	std::string text = req.get_param_value("exposure");
	float value = 0.0f;
	if (!parse_decimal(text, value) || !(std::abs(value) <= 64.0f)) {
		throw Request_Error(400, "exposure: expected a number of stops from -64 to 64, got '" + text + "'");
	}
	return value;
}

// adaptive=T: the threshold of adaptive sampling, 0 for off (Viewer_Session::restart checks its range).
float adaptive_threshold(const std::string& text) {
	float value = 0.0f;
	if (!parse_decimal(text, value)) {
		throw Request_Error(400, "adaptive: expected 0 (off) or a relative precision from 0.001 to 1, got '" + text + "'");
	}
	return value;
}
} // namespace

std::string new_token() {
	std::ifstream random("/dev/urandom", std::ios::binary);
	unsigned char bytes[16];
	if (!random.read(reinterpret_cast<char*>(bytes), sizeof bytes)) throw std::runtime_error("cannot read /dev/urandom");
	std::string token;
	const char* digits = "0123456789abcdef";
	for (unsigned char b : bytes) token += {digits[b >> 4], digits[b & 15]};
	return token;
}

Viewer_Server::Viewer_Server(Viewer_Session& session_, Event_Hub& hub_, std::string token_)
	: session(session_), hub(hub_), token(std::move(token_)), server(std::make_unique<httplib::Server>()) {
	// Event streams hold a thread each while a page is open: more than the default few.
	server->new_task_queue = [] { return new httplib::ThreadPool(16); };
	add_routes();
}

Viewer_Server::~Viewer_Server() = default;

int Viewer_Server::bind(int port) {
	int bound = port == 0 ? server->bind_to_any_port("127.0.0.1") : (server->bind_to_port("127.0.0.1", port) ? port : -1);
	if (bound < 0) throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) +
		                         " (is another viewer running there? ./lab view --port N chooses another port)");
	return bound;
}

void Viewer_Server::serve() {
	server->listen_after_bind();
}

void Viewer_Server::stop() {
	hub.close();
	server->stop();
}

void Viewer_Server::add_routes() {
	httplib::Server& s = *server;
	// Every request carries the token; nothing is served without it.
	s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
		if (req.has_param("token") && same_token(req.get_param_value("token"), token)) {
			return httplib::Server::HandlerResponse::Unhandled;
		}
		send_error(res, 403, "missing or wrong token: open the URL that ./lab view printed");
		return httplib::Server::HandlerResponse::Handled;
	});
	// Request_Error: the status it names; anything else thrown: 500 with its message.
	s.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr thrown) {
		try {
			std::rethrow_exception(thrown);
		} catch (const Request_Error& e) {
			send_error(res, e.status, e.what());
		} catch (const std::exception& e) {
			send_error(res, 500, e.what());
		}
	});
	s.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
		if (res.body.empty()) {
			send_error(res, res.status, res.status == 404 ? "no such page or call: " + req.method + " " + req.path
			                                                : "the request was refused");
		}
	});

	auto page = [this](const std::string& name) {
		return [this, name](const httplib::Request&, httplib::Response& res) {
			const std::string_view* file = page_file(name);
			if (!file) throw Request_Error(404, "the viewer was built without its page file " + name);
			std::string text(*file);
			// The page's own links carry the token too.
			for (size_t at; (at = text.find("{{TOKEN}}")) != std::string::npos;) text.replace(at, 9, token);
			res.set_content(text, content_type(name));
			res.set_header("Cache-Control", "no-store");
		};
	};
	s.Get("/", page("index.html"));
	s.Get("/viewer.js", page("viewer.js"));
	s.Get("/viewer.css", page("viewer.css"));

	s.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) { send_json(res, session.state()); });

	s.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
		auto subscriber = hub.subscribe();
		hub.publish("state", session.state().dump()); // the page starts from the whole state
		res.set_header("Cache-Control", "no-store");
		res.set_chunked_content_provider(
			"text/event-stream",
			[this, subscriber](size_t, httplib::DataSink& sink) {
				std::string event;
				if (hub.next(subscriber, event, std::chrono::milliseconds(1000))) return sink.write(event.data(), event.size());
				if (hub.closed()) return false;
				return sink.write(":\n\n", 3); // a comment: notices a page that has gone
			},
			[this, subscriber](bool) { hub.unsubscribe(subscriber); });
	});

	s.Get("/api/image", [this](const httplib::Request& req, httplib::Response& res) {
		Side side = side_named(required(req, "side", "student or reference"));
		Layer layer = layer_named(required(req, "layer", "mean, variance, non_finite or z"));
		Viewer_Session::Image image = session.image(side, layer);
		res.set_header("X-Width", std::to_string(image.width));
		res.set_header("X-Height", std::to_string(image.height));
		res.set_header("X-Samples", std::to_string(image.samples));
		res.set_header("X-Generation", std::to_string(image.generation));
		res.set_header("Cache-Control", "no-store");
		res.set_content(std::move(image.bytes), "application/octet-stream");
	});

	s.Get("/api/path", [this](const httplib::Request& req, httplib::Response& res) {
		Side side = side_named(required(req, "side", "student or reference"));
		uint32_t x = whole<uint32_t>("x", required(req, "x", "a pixel column"), 0, 16383);
		uint32_t y = whole<uint32_t>("y", required(req, "y", "a pixel row"), 0, 16383);
		uint32_t samples = whole_or<uint32_t>(req, "samples", 1, 1, 1000000);
		uint32_t brightest = whole_or<uint32_t>(req, "brightest", 0, 0, 1000);
		res.set_content(session.follow(side, x, y, samples, brightest), "application/json");
	});

	s.Post("/api/pause", [this](const httplib::Request&, httplib::Response& res) {
		session.pause();
		send_json(res, session.state());
	});
	s.Post("/api/resume", [this](const httplib::Request&, httplib::Response& res) {
		session.resume();
		send_json(res, session.state());
	});
	s.Post("/api/restart", [this](const httplib::Request& req, httplib::Response& res) {
		Viewer_Session::Restart changes;
		if (req.has_param("seed")) changes.seed = whole<uint64_t>("seed", req.get_param_value("seed"), 0, UINT64_MAX - 1);
		if (req.has_param("view")) changes.view = req.get_param_value("view");
		if (req.has_param("scene")) changes.scene = req.get_param_value("scene");
		if (req.has_param("adaptive")) changes.adaptive = adaptive_threshold(req.get_param_value("adaptive"));
		session.restart(changes);
		send_json(res, session.state());
	});
	s.Post("/api/grade", [this](const httplib::Request& req, httplib::Response& res) {
		int task = whole<int>("task", required(req, "task", "a task number from 1 to 8"), 1, 8);
		session.grade(task);
		res.status = 202;
		send_json(res, {{"task", task}, {"started", true}});
	});
	s.Post("/api/snapshot", [this](const httplib::Request& req, httplib::Response& res) {
		Side side = side_named(required(req, "side", "student or reference"));
		std::string path = session.snapshot(side, required(req, "name", "a file name ending in .png"), stops(req));
		send_json(res, {{"wrote", path}});
	});
}
