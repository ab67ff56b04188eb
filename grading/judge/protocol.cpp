#include "protocol.h"

namespace protocol {

namespace {
// The NAME or FUNCTIONS of the request whose KIND is `kind`, or `unknown`.
template<class... Request> const char* find_text(std::tuple<Request...>*, Kind kind, bool functions, const char* unknown) {
	const char* text = unknown;
	// A fold over the list that stops at the first match (the names are never null).
	(void)((kind == Request::KIND && (text = functions ? Request::FUNCTIONS : Request::NAME)) || ...);
	return text;
}
} // namespace

const char* kind_name(Kind kind) {
	return find_text(static_cast<Requests*>(nullptr), kind, false, "an unknown request");
}

const char* kind_functions(Kind kind) {
	return find_text(static_cast<Requests*>(nullptr), kind, true, "an unknown function");
}

} // namespace protocol
