#pragma once
// The judge's side of the protocol (protocol.h): a subject process, started fresh (fork, then exec
// of the subject program in the sandbox, sandbox.h), asked typed, batched requests.
//
// Anything that is not a well-formed answer in turn — a crash, an exit, a limit reached, bytes that
// do not decode, an answer to another request — is a Subject_Failure, whose message says what
// happened, during which request and which student functions, and what the code printed last.
// The subject is then gone; the judge starts a fresh one for the next test case.
#include "protocol.h"
#include "sandbox.h"
#include "wire.h"

#include <chrono>
#include <functional>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/types.h>

struct Subject_Failure : std::runtime_error {
	using std::runtime_error::runtime_error;
};

// The requests that ran out of time (or of CPU time) during one judge's run. A hang costs a whole
// request's time limit, so a submission whose every function hangs would take many minutes: a later
// request of a kind that already hung fails at once, and once hangs have taken two requests' time
// limits, every later request does ("fix those first"), so that a task's grading spends at most that
// on hangs.
struct Hang_Record {
	std::vector<protocol::Kind> kinds;
	double seconds = 0.0; // spent waiting for requests that never answered
};

class Subject {
public:
	using Clock = std::chrono::steady_clock;

	// Starts `program` in `sandbox` (the process starts at once; it is asked nothing before
	// begin()). `hangs`: the judge's record of the requests that ran out of time, consulted and kept
	// up to date.
	Subject(const std::string& program, const Sandbox& sandbox, Hang_Record& hangs);
	// Gives the subject to a test case: `deadline`, when the test case's time is up;
	// `save_requests`, a file to append every request to, for `subject --replay` (empty: none).
	void begin(Clock::time_point deadline, const std::string& save_requests);
	~Subject();
	Subject(const Subject&) = delete;
	Subject& operator=(const Subject&) = delete;

	// Replies to a subject's question during a request (protocol.h: Object_Question): the encoded
	// reply, or wire::Malformed for a question that is not one.
	using Questions = std::function<std::string(const std::string& question)>;

	// `questions`: for a request that asks back (BVH_Instances); empty: a question is malformed.
	template<class Request> typename Request::Answer ask(const Request& request, const Questions& questions = {}) {
		std::string answer;
		try {
			answer = exchange(Request::KIND, wire::encode(request), questions);
		} catch (const std::bad_alloc&) {
			fail(Request::KIND, "sent an answer too large for the judge's memory limit");
		}
		auto decoded = [&] {
			try {
				return wire::decode<typename Request::Answer>(answer);
			} catch (const wire::Malformed& problem) {
				fail(Request::KIND, std::string("answered with bytes that are not an answer (") + problem.what() + ")");
			} catch (const std::bad_alloc&) {
				answer = std::string();
				fail(Request::KIND, "sent an answer too large for the judge's memory limit");
			}
		}();
		if (!request.fits(decoded)) fail(Request::KIND, "answered with a result count its inputs do not call for");
		return decoded;
	}

	// The largest answer the judge reads to a request of `request_bytes`: every answer is a batch of
	// results about the size of the request's inputs (a film is the exception: a few bytes of scene
	// settings, 104 bytes a pixel), so 16 times the request and 64 MiB (a film of 640,000 pixels)
	// bound every answer a correct subject sends. One beyond it is "too large", never read.
	static uint64_t answer_limit(uint64_t request_bytes) {
		return (uint64_t(64) << 20) + 16 * request_bytes;
	}

	// The end of what the subject printed (stdout and stderr), at most `lines` lines.
	std::string printed(size_t lines = 15) const;

private:
	std::string exchange(protocol::Kind kind, const std::string& payload, const Questions& questions);
	[[noreturn]] void fail(protocol::Kind kind, const std::string& what);
	// Why the process ended (waits for it, killing it if it is still running).
	std::string end_reason();
	void stop();

	// Throws if `kind` should fail at once because of earlier hangs (Hang_Record).
	void refuse_after_hangs(protocol::Kind kind) const;

	const Sandbox& sandbox;
	Clock::time_point deadline;
	Hang_Record& hangs;
	std::string save_requests;
	pid_t pid = -1;
	int to_subject = -1, from_subject = -1, log = -1;
	uint32_t sequence = 0;
	bool timed_out = false;
	bool used_up_cpu = false; // killed by its CPU time limit
	std::string timeout_kind; // "request" or "test case"
};
