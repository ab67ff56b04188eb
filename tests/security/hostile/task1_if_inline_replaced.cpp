// Hostile: correct only if its own version of an inline framework function replaces the
// framework's in the subject: Render_Observer::begin (framework/core/render_observer.h, which
// every traced ray calls through the observer's vtable), declared here by hand and defined inline,
// so that its object carries a weak copy beside the framework's. Whichever copy the linker keeps is
// the one every caller runs; taking its address here shows which.
struct Closest_Hit;
struct Render_Observer {
	void begin(const Closest_Hit& event);
};

namespace {
volatile bool mine_ran = false;
}

inline void Render_Observer::begin(const Closest_Hit&) {
	mine_ran = true;
}

static bool attack_worked() {
	static bool worked = [] {
		void (Render_Observer::*volatile begin)(const Closest_Hit&) = &Render_Observer::begin;
		Render_Observer observer;
		(observer.*begin)(*reinterpret_cast<const Closest_Hit*>(&observer)); // the framework's does nothing
		return mine_ran;
	}();
	return worked;
}

@CORRECT_TASK1_IF@
