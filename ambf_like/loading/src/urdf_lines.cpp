#include "urdf_lines.hpp"

#include <tinyxml.h>

#include "ambf_like/load_error.hpp"
#include "common/xml_nesting.hpp"

namespace ambf_like::detail {

namespace {

/// Records `element`'s children under `path`: the k-th of a tag as "path/tag[k]", the first
/// also as "path/tag", down to `depth` levels.
void recordChildren(const TiXmlElement& element, const std::string& path, int depth,
                    std::unordered_map<std::string, int>& lines) {
  std::unordered_map<std::string, int> seen;
  for (const TiXmlElement* child = element.FirstChildElement(); child != nullptr;
       child = child->NextSiblingElement()) {
    const std::string tag = child->ValueStr();
    const int index = seen[tag]++;
    for (const std::string& name :
         {path + "/" + tag + "[" + std::to_string(index) + "]", path + "/" + tag}) {
      if (lines.try_emplace(name, child->Row()).second && depth > 1) {
        recordChildren(*child, name, depth - 1, lines);
      }
    }
  }
}

/// The line of the last node TinyXML read before it failed: the end of its chain of last children
/// (it links each node as it parses it, the failed one too).
int lastReadRow(const TiXmlNode& document) {
  int row = 0;
  for (const TiXmlNode* node = document.LastChild(); node != nullptr; node = node->LastChild()) {
    if (node->Row() > 0) row = node->Row();
  }
  return row;
}

}  // namespace

UrdfLines::UrdfLines(const std::filesystem::path& file, const std::string& text) {
  TiXmlDocument document;
  document.Parse(text.c_str(), nullptr, TIXML_ENCODING_UTF8);
  if (document.Error()) {
    // TinyXML gives no place when its text runs out inside an element, tag, comment or
    // declaration: the line that opens the innermost of them, or else (where TinyXML read a tag
    // differently from XML's rules) the last thing it read.
    const auto open = common::xmlOpenAtEnd(text);
    const int row = document.ErrorRow() > 0 ? document.ErrorRow()
                    : open.has_value()      ? static_cast<int>(*open)
                                            : lastReadRow(document);
    throw LoadError(
        SourceRef{file, row, ""},
        "malformed URDF: " + std::string(document.ErrorDesc()) +
            (document.ErrorRow() > 0 ? " (column " + std::to_string(document.ErrorCol()) + ")"
             : open.has_value()      ? " (the file ends inside what this line opens)"
             : row > 0               ? " (the parser stopped after what this line starts)"
                                     : ""));
  }
  const TiXmlElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) return;
  robot_line_ = robot->Row();
  for (const TiXmlElement* e = robot->FirstChildElement(); e != nullptr;
       e = e->NextSiblingElement()) {
    const char* name = e->Attribute("name");
    if (name == nullptr || (e->ValueStr() != "link" && e->ValueStr() != "joint")) continue;
    const std::string path = e->ValueStr() + "[" + name + "]";
    if (!lines_.try_emplace(path, e->Row()).second) continue;  // urdfdom refuses the repeat
    named_.try_emplace(name, e->Row());
    recordChildren(*e, path, 2, lines_);
  }
}

int UrdfLines::lineOf(const std::string& path) const {
  for (std::string part = path; !part.empty();) {
    if (const auto found = lines_.find(part); found != lines_.end()) return found->second;
    const auto slash = part.rfind('/');
    part.resize(slash == std::string::npos ? 0 : slash);
  }
  return 0;
}

int UrdfLines::lineNamedIn(const std::string& message) const {
  for (std::size_t open = message.find('['); open != std::string::npos;
       open = message.find('[', open + 1)) {
    const std::size_t close = message.find(']', open);
    if (close == std::string::npos) break;
    if (const auto found = named_.find(message.substr(open + 1, close - open - 1));
        found != named_.end()) {
      return found->second;
    }
  }
  return robot_line_;
}

}  // namespace ambf_like::detail
