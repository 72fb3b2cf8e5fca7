#pragma once
// Well-formed UTF-8, checked before text reaches a parser that trusts it: tinyxml (under
// urdfdom) steps over a multi-byte character by its lead byte alone, so a lead byte whose
// continuation is missing at the end of the text walks it past its terminator.

#include <cstddef>
#include <optional>
#include <string_view>

namespace common {

/// The line (1-based) of the first byte of `text` that is not well-formed UTF-8 (RFC 3629: no
/// overlong forms, nothing above U+10FFFF) or is a NUL, if there is one.
std::optional<std::size_t> firstMalformedUtf8Line(std::string_view text);

}  // namespace common
