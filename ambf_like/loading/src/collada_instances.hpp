#pragma once
// A COLLADA file's node instances, checked before assimp follows them: assimp builds each
// <instance_node> by recursing into the node it names, with no guard against a node that
// instances itself (it recurses until the stack ends) or a chain of instances that multiplies into
// more nodes than memory holds.

#include <cstddef>
#include <optional>
#include <string>

namespace ambf_like::detail {

/// The most nodes a COLLADA scene may expand to through its instances: a robot's visual meshes
/// hold some hundreds.
inline constexpr std::size_t kMostColladaNodes = 100000;

/// Where and why a COLLADA text's node instances cannot be built.
struct ColladaInstanceProblem {
  int line = 0;  ///< of the <instance_node> or <node> at fault (1-based)
  std::string what;
};

/// A node that instances itself (directly or through others) or expands to more than
/// kMostColladaNodes nodes, if `text` has one. Text that is not well-formed XML has none here:
/// assimp refuses it on its own.
std::optional<ColladaInstanceProblem> colladaInstanceProblem(const std::string& text);

}  // namespace ambf_like::detail
