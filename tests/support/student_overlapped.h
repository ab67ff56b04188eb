#pragma once
// The judge's work beside the subject's: a test case that asks for many samples in several
// requests counts the answer to one while the subject computes the next, on a thread of its own,
// so that the judge's counting (a chi-square's binning) does not wait for the subject's sampling
// nor the subject for it.
#include "judge.h"

#include <cstddef>
#include <future>

// Asks request(i) for i = 0, 1, ..., count - 1 and calls use(i, answer) for each, in order, each
// call finishing before the next starts; use(i, ...) runs while the subject answers request(i + 1).
// `use` must only compute: Catch2's checks belong on the test case's own thread.
template<class Make_Request, class Use>
void ask_each_while_using_the_last(size_t count, Make_Request request, Use use) {
	std::future<void> using_last;
	for (size_t i = 0; i < count; i++) {
		auto answer = judge::ask(request(i));
		if (using_last.valid()) using_last.get();
		using_last = std::async(std::launch::async, [&use, i, answer = std::move(answer)] { use(i, answer); });
	}
	if (using_last.valid()) using_last.get();
}
