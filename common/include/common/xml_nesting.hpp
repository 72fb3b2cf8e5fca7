#pragma once
// How an XML text nests its elements, read without a recursive parser: the guard in front of the
// parsers that recurse once per level (tinyxml under urdfdom, assimp's COLLADA), and where an
// element is left open.

#include <cstddef>
#include <optional>
#include <string_view>

namespace common {

/// The most elements any XML file of this project's inputs may nest: real URDF and COLLADA files
/// nest a few dozen; the recursive parsers behind them run out of stack some thousands deep.
inline constexpr std::size_t kMostXmlNesting = 500;

/// The line (1-based) on which `text` opens an element deeper than `limit`, if it does.
/// Comments, CDATA, declarations and processing instructions are skipped; quoted attribute
/// values may hold '>'.
std::optional<std::size_t> xmlNestedBeyond(std::string_view text, std::size_t limit);

/// The line (1-based) that opens the innermost element, tag, comment or declaration still open
/// where `text` ends, if any: where a parser that reached the end inside it (and says so without
/// a line) stopped.
std::optional<std::size_t> xmlOpenAtEnd(std::string_view text);

}  // namespace common
