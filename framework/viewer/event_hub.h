#pragma once
// Server-sent events: what happens (a frame, a build, a grader's line) is published once and sent
// to every open page. Each page has a queue; a page that reads too slowly loses its oldest events
// rather than holding the viewer's memory.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

class Event_Hub {
public:
	struct Subscriber {
		std::deque<std::string> queue; // formatted events
		bool closed = false;
	};

	// An event named `name` whose data is `json` (one line), as the text/event-stream format has it.
	void publish(const std::string& name, const std::string& json);

	std::shared_ptr<Subscriber> subscribe();
	void unsubscribe(const std::shared_ptr<Subscriber>& subscriber);

	// The next event for `subscriber`, waiting up to `timeout`: false if none came (or the hub is
	// closed: check closed()).
	bool next(const std::shared_ptr<Subscriber>& subscriber, std::string& event, std::chrono::milliseconds timeout);

	// Wakes every subscriber and ends their streams (the viewer stops).
	void close();
	bool closed() const;

	static constexpr size_t MAX_QUEUED = 256;

private:
	mutable std::mutex mutex;
	std::condition_variable changed;
	std::vector<std::shared_ptr<Subscriber>> subscribers;
	bool is_closed = false;
};
