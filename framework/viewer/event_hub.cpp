#include "event_hub.h"

#include <algorithm>

void Event_Hub::publish(const std::string& name, const std::string& json) {
	std::string event = "event: " + name + "\ndata: " + json + "\n\n";
	std::lock_guard<std::mutex> lock(mutex);
	for (const auto& subscriber : subscribers) {
		if (subscriber->queue.size() >= MAX_QUEUED) subscriber->queue.pop_front();
		subscriber->queue.push_back(event);
	}
	changed.notify_all();
}

std::shared_ptr<Event_Hub::Subscriber> Event_Hub::subscribe() {
	auto subscriber = std::make_shared<Subscriber>();
	std::lock_guard<std::mutex> lock(mutex);
	subscriber->closed = is_closed;
	subscribers.push_back(subscriber);
	return subscriber;
}

void Event_Hub::unsubscribe(const std::shared_ptr<Subscriber>& subscriber) {
	std::lock_guard<std::mutex> lock(mutex);
	subscribers.erase(std::remove(subscribers.begin(), subscribers.end(), subscriber), subscribers.end());
}

bool Event_Hub::next(const std::shared_ptr<Subscriber>& subscriber, std::string& event,
                     std::chrono::milliseconds timeout) {
	std::unique_lock<std::mutex> lock(mutex);
	changed.wait_for(lock, timeout, [&] { return !subscriber->queue.empty() || subscriber->closed; });
	if (subscriber->queue.empty() || subscriber->closed) return false;
	event = std::move(subscriber->queue.front());
	subscriber->queue.pop_front();
	return true;
}

void Event_Hub::close() {
	std::lock_guard<std::mutex> lock(mutex);
	is_closed = true;
	for (const auto& subscriber : subscribers) subscriber->closed = true;
	changed.notify_all();
}

bool Event_Hub::closed() const {
	std::lock_guard<std::mutex> lock(mutex);
	return is_closed;
}
