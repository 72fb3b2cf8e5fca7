#pragma once
// Where a URDF's elements are: the lines behind the paths the URDF reader names in its errors.

#include <filesystem>
#include <string>
#include <unordered_map>

namespace ambf_like::detail {

/// The lines of a URDF's links and joints and of the elements in them, by the reader's paths
/// ("link[base]", "link[base]/inertial", "link[base]/collision[1]/origin", "joint[j1]/limit"),
/// read with TinyXML, the parser urdfdom itself runs, so that both see the same document.
class UrdfLines {
 public:
  /// Reads `text`; throws LoadError naming the line and column of the first thing that is not
  /// well-formed XML (urdfdom only says what, not where).
  UrdfLines(const std::filesystem::path& file, const std::string& text);

  /// The line of the longest leading part of `path` it knows; 0 when it knows none.
  int lineOf(const std::string& path) const;
  /// The line of the first link or joint that `message` names in brackets ("joint [j1]", as
  /// urdfdom's own errors name them); otherwise the <robot> element's.
  int lineNamedIn(const std::string& message) const;

 private:
  std::unordered_map<std::string, int> lines_;
  std::unordered_map<std::string, int> named_;  ///< a link's or joint's line by its name
  int robot_line_ = 0;
};

}  // namespace ambf_like::detail
