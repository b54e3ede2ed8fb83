// UTF-8 text: where a byte string stops being valid UTF-8, and the longest
// prefix that fits a fixed buffer without cutting a character in half.
// Names and catalogue ids travel into JSON, FITS and .scd files, whose
// writers refuse invalid UTF-8.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace eoir {

// The byte offset of the first byte that does not start a valid UTF-8
// character (a stray continuation byte, a truncated sequence, an overlong
// form, a surrogate or a code point past U+10FFFF); npos if all is valid.
std::size_t invalid_utf8_at(std::string_view text);

// What keeps `text` from being printable UTF-8 (valid, no control
// characters), as "not valid UTF-8 at byte 3" or "control character at
// byte 5" (the first problem in the text); "" if nothing does.
std::string printable_utf8_problem(std::string_view text);

// The length of the longest prefix of valid UTF-8 `text` of at most
// max_bytes that ends on a character boundary.
std::size_t utf8_prefix_length(std::string_view text, std::size_t max_bytes);

}  // namespace eoir
