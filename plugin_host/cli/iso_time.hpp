// ISO-8601 UTC strings <-> seconds on a uniform host time line.
//
// The host counts time as seconds since 2000-01-01T12:00:00Z with every day
// 86400 s long (POSIX-like: leap seconds are not counted). The engine gets
// times as ISO strings through eoir_time_from_iso, so the engine's own UTC
// handling stays authoritative; the host scale only orders and steps times.
#pragma once
#include <string>

namespace eoir::cli {

// Parses "YYYY-MM-DDThh:mm:ss[.fff][Z]" (also a space for 'T', or a date
// alone). Throws std::invalid_argument with a message naming the problem.
double parse_iso(const std::string& iso);
// Formats as "YYYY-MM-DDThh:mm:ss.sssZ" (milliseconds; ".sss" dropped when 0).
std::string format_iso(double seconds);

}  // namespace eoir::cli
