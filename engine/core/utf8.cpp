#include "core/utf8.hpp"

namespace eoir {
namespace {
// The length of the valid character at text[i], 0 if there is none.
std::size_t character_length(std::string_view text, std::size_t i) {
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  const unsigned char c = s[i];
  const std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (len == 0 || i + len > n) return 0;
  for (std::size_t k = 1; k < len; ++k)
    if ((s[i + k] >> 6) != 0x2) return 0;
  if (len == 1) return 1;
  // No overlong forms, surrogates or code points past U+10FFFF.
  const unsigned cp = len == 2   ? ((c & 0x1fu) << 6) | (s[i + 1] & 0x3fu)
                      : len == 3 ? ((c & 0x0fu) << 12) | ((s[i + 1] & 0x3fu) << 6) | (s[i + 2] & 0x3fu)
                                 : ((c & 0x07u) << 18) | ((s[i + 1] & 0x3fu) << 12) | ((s[i + 2] & 0x3fu) << 6) |
                                       (s[i + 3] & 0x3fu);
  const unsigned min_cp = len == 2 ? 0x80u : len == 3 ? 0x800u : 0x10000u;
  return cp >= min_cp && cp <= 0x10ffffu && !(cp >= 0xd800u && cp <= 0xdfffu) ? len : 0;
}
}  // namespace

std::size_t invalid_utf8_at(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t len = character_length(text, i);
    if (len == 0) return i;
    i += len;
  }
  return std::string_view::npos;
}

std::string printable_utf8_problem(std::string_view text) {
  std::size_t control = std::string_view::npos;
  for (std::size_t i = 0; i < text.size() && control == std::string_view::npos; ++i)
    if (static_cast<unsigned char>(text[i]) < 0x20 || text[i] == 0x7f) control = i;
  const std::size_t invalid = invalid_utf8_at(text);
  if (invalid < control) return "not valid UTF-8 at byte " + std::to_string(invalid);
  if (control != std::string_view::npos) return "control character at byte " + std::to_string(control);
  return {};
}

std::size_t utf8_prefix_length(std::string_view text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return text.size();
  std::size_t end = max_bytes;
  // Back over continuation bytes to the start of the character cut at max_bytes.
  while (end > 0 && (static_cast<unsigned char>(text[end]) >> 6) == 0x2) --end;
  return end;
}

}  // namespace eoir
