// What the judge's own listeners and its reporter see of a Catch2 run, the same with Catch2 2 and 3
// (lab_catch2.h says which machines have which). Catch2 3 renamed the listener base, passes its
// configuration and test-case info by pointer, keeps tags as string views, makes a reporter's
// assertionEnded return nothing and compiles its runner into a library: the adapters below take
// those differences, and the lab's code (grading/judge/, grading/report/report_listener.cpp) is
// written once against Events.
//
// In a file that includes this header, Catch2 2 needs its reporter interfaces declared: include
// this before lab_catch2.h. The runner's part of the seam is catch2_session.h.
#pragma once

#if LAB_CATCH2_MAJOR == 2
#ifndef CATCH_CONFIG_EXTERNAL_INTERFACES
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#endif
#include <catch2/catch.hpp>
#else
#include <catch2/catch_test_case_info.hpp>
#include <catch2/interfaces/catch_interfaces_capture.hpp>
#include <catch2/interfaces/catch_interfaces_config.hpp>
#include <catch2/internal/catch_test_case_registry_impl.hpp>
#include <catch2/reporters/catch_reporter_event_listener.hpp>
#include <catch2/reporters/catch_reporter_registrars.hpp>
#include <catch2/reporters/catch_reporter_streaming_base.hpp>
#endif

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace catch2_seam {

// Files are named relative to the working directory (the repository's root, where judges run).
struct Test_Case {
	std::string name;
	std::vector<std::string> tags; // as written, without brackets: "id:t1.ray.centre", "fn:generate_ray"
	std::string file;
	size_t line = 0;

	// The rest of each tag that starts with `prefix`: tagged("fn:") = {"generate_ray"}.
	std::vector<std::string> tagged(const std::string& prefix) const {
		std::vector<std::string> values;
		for (const std::string& tag : tags) {
			if (tag.rfind(prefix, 0) == 0) values.push_back(tag.substr(prefix.size()));
		}
		return values;
	}
};

struct Message {
	std::string macro; // INFO, CAPTURE, or the check's own macro for its message (FAIL's text, ...)
	std::string text;
};

struct Failed_Check {
	std::string kind; // "check", "failure" (FAIL), "unexpected exception", "expected an exception", "crash"
	std::string file;
	size_t line = 0;
	std::string expression; // as written, e.g. "CHECK( ok )", or empty
	std::string expansion;  // with its values, e.g. "false", or empty
	std::string result_message; // the check's own message: FAIL's text, an exception's, a signal's name
	std::vector<Message> messages; // in scope when it failed (INFO, CAPTURE), then result_message if any
};

struct Counts {
	size_t passed = 0, failed = 0;
};

// A listener (LAB_CATCH2_LISTENER) or a reporter (LAB_CATCH2_REPORTER, constructed with the
// reporter's stream) overrides what it needs.
class Events {
public:
	virtual ~Events() = default;
	virtual void run_starting(const std::string& program, const std::vector<Test_Case>& all_test_cases) {}
	virtual void test_case_starting(const Test_Case& test_case) {}
	virtual void section_starting() {}
	virtual void check_failed(const Failed_Check& check) {}
	virtual void test_case_ended(const Test_Case& test_case, Counts checks) {}
	virtual void run_ended(Counts test_cases, Counts checks) {}
};

// A message that every check of the running section carries before its own (call it from
// section_starting).
inline void push_note(const std::string& text) {
	static const Catch::SourceLineInfo here(__FILE__, __LINE__);
	Catch::MessageInfo note("INFO", here, Catch::ResultWas::Info);
	note.message = text;
	Catch::getResultCapture().pushScopedMessage(note);
}

namespace detail {

inline std::string relative(const char* file) {
	std::error_code error;
	std::filesystem::path path = std::filesystem::proximate(file, error);
	return error ? std::string(file) : path.string();
}

inline std::string result_kind(Catch::ResultWas::OfType type) {
	switch (type) {
	case Catch::ResultWas::ThrewException: return "unexpected exception";
	case Catch::ResultWas::DidntThrowException: return "expected an exception";
	case Catch::ResultWas::FatalErrorCondition: return "crash";
	case Catch::ResultWas::ExplicitFailure: return "failure";
	default: return "check";
	}
}

inline Test_Case test_case(const Catch::TestCaseInfo& info) {
	Test_Case t{info.name, {}, relative(info.lineInfo.file), info.lineInfo.line};
#if LAB_CATCH2_MAJOR == 2
	t.tags = info.tags;
#else
	for (const Catch::Tag& tag : info.tags) t.tags.emplace_back(tag.original.data(), tag.original.size());
#endif
	return t;
}

inline std::vector<Test_Case> all_test_cases(const Catch::IConfig& config) {
	std::vector<Test_Case> all;
#if LAB_CATCH2_MAJOR == 2
	for (const Catch::TestCase& test : Catch::getAllTestCasesSorted(config)) all.push_back(test_case(test));
#else
	for (const Catch::TestCaseHandle& test : Catch::getAllTestCasesSorted(config)) {
		all.push_back(test_case(test.getTestCaseInfo()));
	}
#endif
	return all;
}

inline Failed_Check failed_check(const Catch::AssertionStats& stats) {
	const Catch::AssertionResult& result = stats.assertionResult;
	Failed_Check check{result_kind(result.getResultType()),
	                   relative(result.getSourceInfo().file),
	                   result.getSourceInfo().line,
	                   result.hasExpression() ? result.getExpressionInMacro() : "",
	                   result.hasExpandedExpression() ? result.getExpandedExpression() : "",
	                   result.hasMessage() ? std::string(result.getMessage()) : "",
	                   {}};
	for (const Catch::MessageInfo& info : stats.infoMessages) {
		check.messages.push_back({std::string(info.macroName), info.message});
	}
	return check;
}

inline Counts counts(const Catch::Counts& c) {
	return {c.passed, c.failed};
}

inline const Catch::TestCaseInfo& info_of(const Catch::TestCaseStats& stats) {
#if LAB_CATCH2_MAJOR == 2
	return stats.testInfo;
#else
	return *stats.testInfo;
#endif
}

// The events Catch2 reports, converted and passed on to `events` (Base: a listener's or a
// reporter's base class, which sees them first). A reporter's T is made with its output stream.
template <class Base, class T>
class Forward : public Base {
public:
	template <class Config>
	explicit Forward(Config&& config) : Base(std::forward<Config>(config)), events(make_events()) {}

	void testRunStarting(const Catch::TestRunInfo& info) override {
		Base::testRunStarting(info);
		events.run_starting(std::string(info.name), all_test_cases(*this->m_config));
	}
	void testCaseStarting(const Catch::TestCaseInfo& info) override {
		Base::testCaseStarting(info);
		events.test_case_starting(test_case(info));
	}
	void sectionStarting(const Catch::SectionInfo& info) override {
		Base::sectionStarting(info);
		events.section_starting();
	}
#if LAB_CATCH2_MAJOR == 2
	void assertionStarting(const Catch::AssertionInfo&) override {}
	bool assertionEnded(const Catch::AssertionStats& stats) override {
		if (!stats.assertionResult.isOk()) events.check_failed(failed_check(stats));
		return false; // unused by Catch2 2.13
	}
#else
	void assertionEnded(const Catch::AssertionStats& stats) override {
		Base::assertionEnded(stats);
		if (!stats.assertionResult.isOk()) events.check_failed(failed_check(stats));
	}
#endif
	void testCaseEnded(const Catch::TestCaseStats& stats) override {
		Base::testCaseEnded(stats);
		events.test_case_ended(test_case(info_of(stats)), counts(stats.totals.assertions));
	}
	void testRunEnded(const Catch::TestRunStats& stats) override {
		Base::testRunEnded(stats);
		events.run_ended(counts(stats.totals.testCases), counts(stats.totals.assertions));
	}

private:
	T make_events() {
		if constexpr (std::is_constructible_v<T, std::ostream&>) {
#if LAB_CATCH2_MAJOR == 2
			return T(this->stream);
#else
			return T(this->m_stream);
#endif
		} else {
			return T();
		}
	}

	T events;
};

#if LAB_CATCH2_MAJOR == 2
template <class T>
using Listener = Forward<Catch::TestEventListenerBase, T>;
template <class T>
class Reporter : public Forward<Catch::StreamingReporterBase<Reporter<T>>, T> {
public:
	using Forward<Catch::StreamingReporterBase<Reporter<T>>, T>::Forward;
	static std::string getDescription() { return T::DESCRIPTION; }
};
#else
template <class T>
using Listener = Forward<Catch::EventListenerBase, T>;
template <class T>
class Reporter : public Forward<Catch::StreamingReporterBase, T> {
public:
	using Forward<Catch::StreamingReporterBase, T>::Forward;
	static std::string getDescription() { return T::DESCRIPTION; }
};
#endif

} // namespace detail

} // namespace catch2_seam

// Registers the Events class `type` (default-constructible) as a listener, or as the reporter
// `name` (constructed with the reporter's stream; `type::DESCRIPTION` is its -r description).
#define LAB_CATCH2_LISTENER(type)                                  \
	using type##_Listener = catch2_seam::detail::Listener<type>; \
	CATCH_REGISTER_LISTENER(type##_Listener)
#define LAB_CATCH2_REPORTER(name, type)                            \
	using type##_Reporter = catch2_seam::detail::Reporter<type>; \
	CATCH_REGISTER_REPORTER(name, type##_Reporter)
