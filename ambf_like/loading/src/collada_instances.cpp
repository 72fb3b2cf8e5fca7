#include "collada_instances.hpp"

#include <tinyxml.h>

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace ambf_like::detail {

namespace {

/// One <node> and what building it builds: its nested nodes and the nodes it instances.
struct NodeEntry {
  const TiXmlElement* element = nullptr;
  std::vector<std::size_t> children;
  std::vector<const TiXmlElement*> through;  ///< per child: the element that adds it
};

/// Every <node> of the document in document order, each with its children resolved.
std::vector<NodeEntry> nodesOf(const TiXmlDocument& document) {
  std::vector<NodeEntry> nodes;
  std::unordered_map<const TiXmlElement*, std::size_t> index_of;
  std::unordered_map<std::string, std::size_t> by_id;
  std::vector<const TiXmlElement*> pending{document.RootElement()};
  while (!pending.empty()) {
    const TiXmlElement* element = pending.back();
    pending.pop_back();
    if (element == nullptr) continue;
    if (element->ValueStr() == "node") {
      index_of.emplace(element, nodes.size());
      if (const char* id = element->Attribute("id")) by_id.emplace(id, nodes.size());
      nodes.push_back({element, {}, {}});
    }
    for (const TiXmlElement* child = element->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      pending.push_back(child);
    }
  }
  for (NodeEntry& node : nodes) {
    for (const TiXmlElement* child = node.element->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      if (child->ValueStr() == "node") {
        node.children.push_back(index_of.at(child));
        node.through.push_back(child);
      } else if (child->ValueStr() == "instance_node") {
        const char* url = child->Attribute("url");
        std::string target = url == nullptr ? "" : url;
        if (!target.empty() && target.front() == '#') target.erase(0, 1);
        if (auto it = by_id.find(target); it != by_id.end()) {
          node.children.push_back(it->second);
          node.through.push_back(child);
        }
      }
    }
  }
  return nodes;
}

std::string nameOf(const TiXmlElement& node) {
  const char* id = node.Attribute("id");
  const char* name = node.Attribute("name");
  return id != nullptr ? id : name != nullptr ? name : "(unnamed)";
}

}  // namespace

std::optional<ColladaInstanceProblem> colladaInstanceProblem(const std::string& text) {
  TiXmlDocument document;
  document.Parse(text.c_str(), nullptr, TIXML_ENCODING_UTF8);
  if (document.Error()) return std::nullopt;
  const std::vector<NodeEntry> nodes = nodesOf(document);

  // Depth first without recursion (a chain of instances may be as long as the file): each
  // node's expanded size once all it builds is done, a node met again while open is a loop.
  enum class Visit : char { kNew, kOpen, kDone };
  std::vector<Visit> visit(nodes.size(), Visit::kNew);
  std::vector<std::size_t> size(nodes.size(), 1);
  struct Frame {
    std::size_t node, next_child;
  };
  for (std::size_t root = 0; root < nodes.size(); ++root) {
    if (visit[root] != Visit::kNew) continue;
    std::vector<Frame> stack{{root, 0}};
    visit[root] = Visit::kOpen;
    while (!stack.empty()) {
      Frame& frame = stack.back();
      const NodeEntry& node = nodes[frame.node];
      if (frame.next_child == node.children.size()) {
        for (std::size_t child : node.children) {
          size[frame.node] = std::min(size[frame.node] + size[child], kMostColladaNodes + 1);
        }
        if (size[frame.node] > kMostColladaNodes) {
          return ColladaInstanceProblem{node.element->Row(), "node '" + nameOf(*node.element) +
                                                                 "' expands to more than " +
                                                                 std::to_string(kMostColladaNodes) +
                                                                 " nodes through its instances"};
        }
        visit[frame.node] = Visit::kDone;
        stack.pop_back();
        continue;
      }
      const std::size_t k = frame.next_child++;
      const std::size_t child = node.children[k];
      if (visit[child] == Visit::kOpen) {
        return ColladaInstanceProblem{node.through[k]->Row(),
                                      "node '" + nameOf(*nodes[child].element) +
                                          "' instances itself (through node '" +
                                          nameOf(*node.element) + "')"};
      }
      if (visit[child] == Visit::kNew) {
        visit[child] = Visit::kOpen;
        stack.push_back({child, 0});
      }
    }
  }
  return std::nullopt;
}

}  // namespace ambf_like::detail
