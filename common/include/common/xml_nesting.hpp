#pragma once
// How deep an XML text nests its elements, measured without a recursive parser: the guard in
// front of the parsers that recurse once per level (tinyxml under urdfdom, assimp's COLLADA).

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

}  // namespace common
