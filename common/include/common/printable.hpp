#pragma once
// Untrusted text made safe to log: control bytes escaped, and cut to a bounded length.

#include <cstddef>
#include <string>
#include <string_view>

namespace common {

/// `text` with newlines, tabs and other control or non-ASCII bytes written as escapes (\n, \t,
/// \xNN), cut after `max_chars` input bytes with a note of how many more there were.
std::string printable(std::string_view text, std::size_t max_chars = 200);

}  // namespace common
